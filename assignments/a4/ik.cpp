// Your code: tasks A4.T4 (the iteration) and A4.T5 (the bonus: limits, stable and restore).
// Read assignments/a4/handout/T4-iteration.md and T5-limits-stable.md first.
#include "jelly/a4/ik.hpp"

namespace jelly::a4 {

skeleton::IkResult ik_iterate(const skeleton::Skeleton& skeleton, const std::vector<int>& chain,
                              const Vec3& target, const skeleton::IkSettings& settings,
                              const skeleton::IkOps& ops, skeleton::Posture& posture) {
  // TODO(A4.T4): at most settings.max_iterations updates: p = ops.end_effector(posture); stop when
  // |target − p| < ε; else J (ops.jacobian), x (ops.solve), θ_i[k] += (step·x[3b + k])·180/π for
  // the chain's channels, ops.clamp(posture) when settings.limits. Return the updates made and
  // the last |target − p|. assignments/a4/handout/T4-iteration.md.
  (void)skeleton;
  (void)chain;
  (void)target;
  (void)settings;
  (void)ops;
  (void)posture;
  return {};
}

void clamp_to_limits(const skeleton::Skeleton& skeleton, const std::vector<int>& chain,
                     skeleton::Posture& posture) {
  // TODO(A4.T5): each channel of each chain bone with limits into [lo, hi] (bones[i].limits, in
  // the order of bones[i].channels); the root and bones without limits untouched.
  // assignments/a4/handout/T5-limits-stable.md.
  (void)skeleton;
  (void)chain;
  (void)posture;
}

skeleton::IkResult ik_solve(const skeleton::IkSettings& settings, const skeleton::IkOps& ops,
                            skeleton::Posture& posture) {
  // TODO(A4.T5): r = ops.iterate(posture); stable when r.error < ε; if not stable and
  // settings.restore, put the input posture back (keep a copy).
  // assignments/a4/handout/T5-limits-stable.md.
  (void)settings;
  (void)ops;
  (void)posture;
  return {};
}

}  // namespace jelly::a4
