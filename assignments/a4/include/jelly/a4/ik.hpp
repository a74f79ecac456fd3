// Student tasks A4.T4 (the iteration) and A4.T5 (the bonus: limits, stable and restore) of an
// inverse-kinematics solve (kinematics contract §6.4, §6.5, decision §11.14). Both call their
// collaborators through `ops` (jelly/skeleton/ik.hpp), never your own functions, so that each is
// graded alone. Handout: assignments/a4/handout/T4-iteration.md, T5-limits-stable.md.
#pragma once

#include <vector>

#include "jelly/skeleton_tasks.hpp"

namespace jelly::a4 {

/// A4.T4 — the iteration of §6.4: for it = 0 … settings.max_iterations − 1: p =
/// ops.end_effector(posture), e = target − p; stop when |e| < ε; else J from ops.jacobian, x from
/// ops.solve, and for each chain entry b (bone i), each rotation channel k the bone has
/// (the root: all three), θ_i[k] += (step·x[3b + k])·180/π; then ops.clamp(posture) when
/// settings.limits. Changes only the chain's rotation channels (never the root's translation);
/// returns the updates made and |target − p| after the last forward kinematics (`stable` is
/// left to ik_solve).
skeleton::IkResult ik_iterate(const skeleton::Skeleton& skeleton, const std::vector<int>& chain,
                              const Vec3& target, const skeleton::IkSettings& settings,
                              const skeleton::IkOps& ops, skeleton::Posture& posture);

/// A4.T5 (bonus) — clamps each channel of each bone of `chain` that has limits into [lo, hi]
/// (skeleton.bones[i].limits, one per channel in the `dof` line's order); bones without limits
/// and the root are untouched.
void clamp_to_limits(const skeleton::Skeleton& skeleton, const std::vector<int>& chain,
                     skeleton::Posture& posture);

/// A4.T5 (bonus) — the solve of §6.5: r = ops.iterate(posture); r.stable = r.error < ε; if not
/// stable and settings.restore, the posture becomes the input posture again, bit for bit;
/// r.error stays the one measured before the restore (§11.14).
skeleton::IkResult ik_solve(const skeleton::IkSettings& settings, const skeleton::IkOps& ops,
                            skeleton::Posture& posture);

}  // namespace jelly::a4
