// Inverse kinematics through the SkeletonTasks slots (jelly/skeleton_ik.hpp): the IkOps a
// student's iteration and solve call, each checking what its slot returns, and one chain's solve.
#include "jelly/skeleton_ik.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "skeleton_play.hpp"

namespace jelly {

namespace {

using skeleton::BoneFrames;
using skeleton::IkOps;
using skeleton::IkResult;
using skeleton::Matrix3X;
using skeleton::Posture;
using skeleton::Skeleton;
using skeleton::VectorX;

[[noreturn]] void task_error(const char* task, const std::string& where, const std::string& what) {
  throw std::runtime_error("task " + std::string(task) + (where.empty() ? "" : ", " + where) +
                           ": " + what);
}

using bodies::counted;

bool finite(const Vec3& v) { return v.allFinite(); }

void check_posture(const char* task, const std::string& where, const Skeleton& s,
                   const Posture& p) {
  if (p.angles.size() != s.bones.size())
    task_error(task, where,
               "left a posture of " + counted(p.angles.size(), "angle triple") +
                   "; the skeleton has " + counted(s.bones.size(), "bone"));
  for (std::size_t b = 0; b < p.angles.size(); ++b)
    if (!finite(p.angles[b]))
      task_error(task, where, "left a non-finite angle on bone " + s.bones[b].name);
}

/// Forward kinematics of `p` through the slot, its sizes checked.
void frames_of(const Skeleton& s, const SkeletonTasks& t, const std::string& where,
               const Posture& p, BoneFrames& f) {
  t.forward_kinematics(s, p, f);
  const std::size_t n = s.bones.size();
  if (f.rotation.size() != n || f.start.size() != n || f.end.size() != n)
    task_error("forward_kinematics", where,
               "returned " + counted(f.start.size(), "start") + ", " +
                   counted(f.end.size(), "end") + " and " + counted(f.rotation.size(), "rotation") +
                   "; the skeleton has " + counted(n, "bone"));
}

/// Every bone's angles and the root translation of `after` equal `before`'s, bit for bit, but the
/// channels the chain's bones have (contract §6.4, §10: IK touches only the chain's channels).
std::string foreign_change(const Skeleton& s, const std::vector<int>& chain, const Posture& before,
                           const Posture& after) {
  if (!(after.root_translation.array() == before.root_translation.array()).all())
    return "the root's translation";
  for (std::size_t b = 0; b < s.bones.size(); ++b) {
    const bool in_chain = std::find(chain.begin(), chain.end(), static_cast<int>(b)) != chain.end();
    for (int k = 0; k < 3; ++k) {
      const bool may = in_chain && (b == 0 || s.bones[b].has_rotation(k));
      if (!may && !(after.angles[b][k] == before.angles[b][k]))
        return "bone " + s.bones[b].name + "'s " + "xyz"[k] + " angle";
    }
  }
  return "";
}

/// The frames of the last posture the ops took forward, shared by end_effector and jacobian: the
/// iteration asks for both at the same posture (§6.4), so the second reuses the first's forward
/// kinematics (the same frames, so the same bits) instead of running it again.
struct LastFrames {
  Posture posture;
  BoneFrames frames;
  bool valid = false;

  bool is(const Posture& p) const {
    if (!valid || p.angles.size() != posture.angles.size() ||
        !(p.root_translation.array() == posture.root_translation.array()).all())
      return false;
    for (std::size_t b = 0; b < p.angles.size(); ++b)
      if (!(p.angles[b].array() == posture.angles[b].array()).all()) return false;
    return true;
  }
  /// The frames of `p`: the last ones when `p` is the last posture, bit for bit, else new ones.
  const BoneFrames& of(const Skeleton& s, const SkeletonTasks& t, const std::string& where,
                       const Posture& p) {
    if (is(p)) return frames;
    valid = false;
    frames_of(s, t, where, p, frames);
    posture = p;
    valid = true;
    return frames;
  }
};

}  // namespace

std::string missing_ik_slot(const SkeletonTasks& t) {
  if (!t.forward_kinematics) return "forward_kinematics";
  if (!t.ik_chain) return "ik_chain";
  if (!t.ik_jacobian) return "ik_jacobian";
  if (!t.least_squares) return "least_squares";
  if (!t.clamp_to_limits) return "clamp_to_limits";
  if (!t.ik_iterate) return "ik_iterate";
  if (!t.ik_solve) return "ik_solve";
  return "";
}

IkOps make_ik_ops(const Skeleton& skeleton, const SkeletonTasks& tasks,
                  const std::vector<int>& chain, const IkSolveRequest& request) {
  IkOps ops;
  const Skeleton* s = &skeleton;
  const SkeletonTasks* t = &tasks;
  const std::string where = request.where;
  const int end = chain.front();
  const auto last = std::make_shared<LastFrames>();
  ops.end_effector = [s, t, where, end, last, target = request.target,
                      errors = request.errors](const Posture& p) {
    const BoneFrames& f = last->of(*s, *t, where, p);
    if (!finite(f.end[end]))
      task_error("forward_kinematics", where,
                 "returned a non-finite end of bone " + s->bones[end].name + ", the end effector");
    if (errors) errors->push_back((target - f.end[end]).norm());
    return Vec3(f.end[end]);
  };
  ops.jacobian = [s, t, where, chain, last](const Posture& p, Matrix3X& J) {
    t->ik_jacobian(*s, last->of(*s, *t, where, p), chain, J);
    const auto cols = static_cast<Eigen::Index>(3 * chain.size());
    if (J.cols() != cols)
      task_error("ik_jacobian", where,
                 "returned J of 3 × " + std::to_string(J.cols()) + "; expected 3 × " +
                     std::to_string(cols) + " (3 columns per bone of a chain of " +
                     counted(chain.size(), "bone") + ", kinematics contract §6.2)");
    if (!J.allFinite()) task_error("ik_jacobian", where, "returned a J with a non-finite entry");
  };
  ops.solve = [t, where](const Matrix3X& J, const Vec3& e, VectorX& x) {
    t->least_squares(J, e, x);
    if (x.size() != J.cols())
      task_error("least_squares", where,
                 "returned x of " + std::to_string(x.size()) + " entries; J has " +
                     std::to_string(J.cols()) + " columns (kinematics contract §6.3)");
    if (!x.allFinite())
      task_error("least_squares", where,
                 "returned an x with a non-finite entry for a finite J and e (kinematics contract "
                 "§6.3: finite in, finite out)");
  };
  ops.clamp = [s, t, where, chain](Posture& p) {
    t->clamp_to_limits(*s, chain, p);
    check_posture("clamp_to_limits", where, *s, p);
  };
  ops.iterate = [s, t, where, chain, request, inner = ops](Posture& p) {
    const IkResult r = t->ik_iterate(*s, chain, request.target, request.settings, inner, p);
    check_posture("ik_iterate", where, *s, p);
    if (r.updates < 0 || r.updates > request.settings.max_iterations)
      task_error("ik_iterate", where,
                 "returned " + std::to_string(r.updates) + " updates; expected 0 to " +
                     std::to_string(request.settings.max_iterations) + " (max_iterations)");
    return r;
  };
  return ops;
}

std::vector<int> ik_chain_of(const Skeleton& skeleton, const SkeletonTasks& tasks,
                             const IkSolveRequest& request) {
  const std::vector<int> chain = tasks.ik_chain(skeleton, request.start_bone, request.end_bone);
  if (chain.empty()) task_error("ik_chain", request.where, "returned an empty chain");
  for (int b : chain)
    if (b < 0 || b >= static_cast<int>(skeleton.bones.size()))
      task_error("ik_chain", request.where,
                 "returned bone " + std::to_string(b) + "; the skeleton has " +
                     counted(skeleton.bones.size(), "bone"));
  if (chain.front() != request.end_bone)
    task_error("ik_chain", request.where,
               "returned a chain that starts at bone " + skeleton.bones[chain.front()].name +
                   "; it starts at the end bone, " + skeleton.bones[request.end_bone].name +
                   " (kinematics contract §6.1)");
  return chain;
}

IkResult solve_ik(const Skeleton& skeleton, const SkeletonTasks& tasks,
                  const IkSolveRequest& request, Posture& posture) {
  const std::vector<int> chain = ik_chain_of(skeleton, tasks, request);
  const IkOps ops = make_ik_ops(skeleton, tasks, chain, request);
  const Posture before = posture;
  const IkResult r = tasks.ik_solve(request.settings, ops, posture);
  check_posture("ik_solve", request.where, skeleton, posture);
  const std::string changed = foreign_change(skeleton, chain, before, posture);
  if (!changed.empty())
    task_error("ik_solve", request.where,
               "changed " + changed +
                   ", which is not a channel of the chain (kinematics contract §10: IK touches "
                   "only the chain's bones)");
  if (std::isnan(r.error)) task_error("ik_solve", request.where, "returned the error NaN");
  return r;
}

}  // namespace jelly
