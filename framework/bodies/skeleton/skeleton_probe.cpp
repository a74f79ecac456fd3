// The smoke tests of the skeleton's TaskTable slots (jelly/task_probe.hpp). Each calls its slot on
// a root and one bone `a` (direction +y, length 1, channels rx ry rz) made in code, and counts it
// implemented when the answer differs from what a stub that fills nothing gives (the identity,
// zeros, nothing, an error of ∞). An answer of the wrong size counts as implemented (never read
// past it). The inverse-kinematics slots get their collaborators (IkOps) made here too.
#include "skeleton_probe.hpp"

#include <cmath>

#include "jelly/skeleton_tasks.hpp"
#include "param_table.hpp"

namespace jelly::bodies {

namespace {

using params_detail::format_double;
using skeleton::Channel;
using skeleton::Motion;
using skeleton::Posture;
using skeleton::Skeleton;

Skeleton probe_skeleton() {
  Skeleton s;
  s.scale = 1.0;
  s.bones.resize(2);
  s.bones[0].name = "root";
  s.bones[0].children = {1};
  s.bones[0].channels = {Channel::tx, Channel::ty, Channel::tz,
                         Channel::rx, Channel::ry, Channel::rz};
  s.bones[1].name = "a";
  s.bones[1].parent = 0;
  s.bones[1].channels = {Channel::rx, Channel::ry, Channel::rz};
  s.bones[1].direction = Vec3(0.0, 1.0, 0.0);
  s.bones[1].length = 1.0;
  skeleton::derive_bone_data(s);
  return s;
}

Posture probe_posture(const Vec3& root, const Vec3& a_angles) {
  Posture p = Posture::zero(2);
  p.root_translation = root;
  p.angles[1] = a_angles;
  return p;
}

std::string vec_text(const Vec3& v) {
  return "(" + format_double(v.x()) + ", " + format_double(v.y()) + ", " + format_double(v.z()) +
         ")";
}

TaskStatus missing(std::string id, std::string name) {
  return {std::move(id), std::move(name), false, "function missing from the task table", {}};
}

TaskStatus probe_local_rotation(std::string id, std::string name, const SkeletonTasks& t) {
  if (!t.local_rotation) return missing(std::move(id), std::move(name));
  const skeleton::Mat3 r = t.local_rotation(Vec3(30.0, 20.0, 10.0));
  const bool stub = r == skeleton::Mat3::Identity() || r == skeleton::Mat3::Zero();
  return {std::move(id),
          std::move(name),
          !stub,
          stub ? "E(30°, 20°, 10°) is the identity or zero" : "E(30°, 20°, 10°) is a rotation",
          {}};
}

TaskStatus probe_forward_kinematics(std::string id, std::string name, const SkeletonTasks& t) {
  if (!t.forward_kinematics) return missing(std::move(id), std::move(name));
  skeleton::BoneFrames f;
  t.forward_kinematics(probe_skeleton(), probe_posture(Vec3(1.0, 2.0, 3.0), Vec3(90.0, 0.0, 0.0)),
                       f);
  if (f.start.size() != 2 || f.end.size() != 2)
    return {std::move(id),
            std::move(name),
            true,
            "returned " + std::to_string(f.end.size()) + " bone ends for 2 bones",
            {}};
  const bool stub = f.end[1] == f.start[1];
  return {std::move(id),
          std::move(name),
          !stub,
          stub ? "a bone of length 1 ends where it starts, " + vec_text(f.end[1])
               : "a bone of length 1 from " + vec_text(f.start[1]) + " to " + vec_text(f.end[1]),
          {}};
}

TaskStatus probe_time_map(std::string id, std::string name, const SkeletonTasks& t) {
  if (!t.time_map) return missing(std::move(id), std::move(name));
  skeleton::TimeWarp w;
  w.input_frames = 3;
  w.output_frames = 5;
  const double s = t.time_map(2, w);
  return {std::move(id),
          std::move(name),
          s != 0.0,
          "s(2) = " + format_double(s) + " for a uniform warp of 3 to 5 frames",
          {}};
}

Motion two_frames() {
  Motion m;
  m.frames = {probe_posture(Vec3::Zero(), Vec3::Zero()),
              probe_posture(Vec3(2.0, 0.0, 0.0), Vec3(0.0, 0.0, 40.0))};
  return m;
}

TaskStatus probe_warped_posture(std::string id, std::string name, const SkeletonTasks& t) {
  if (!t.warped_posture) return missing(std::move(id), std::move(name));
  Posture p = Posture::zero(2);
  t.warped_posture(probe_skeleton(), two_frames(), 0.5, p);
  if (p.angles.size() != 2)
    return {std::move(id),
            std::move(name),
            true,
            "returned " + std::to_string(p.angles.size()) + " angle triples for 2 bones",
            {}};
  const bool stub = p.root_translation == Vec3::Zero() && p.angles[1] == Vec3::Zero();
  return {std::move(id),
          std::move(name),
          !stub,
          "halfway between two postures: root " + vec_text(p.root_translation) + ", bone a " +
              vec_text(p.angles[1]) + "°",
          {}};
}

TaskStatus probe_blend(std::string id, std::string name, const SkeletonTasks& t) {
  if (!t.blend_motions) return missing(std::move(id), std::move(name));
  const Motion m = two_frames();
  Motion a = m, b = m, out;
  a.frames.push_back(m.frames[1]);
  b.frames.push_back(m.frames[0]);
  t.blend_motions(probe_skeleton(), a, b, skeleton::Blend{1, 1, 2}, out);
  return {std::move(id),
          std::move(name),
          !out.frames.empty(),
          std::to_string(out.frames.size()) + " frames from A and B of 3 (a 1, b 1, window 2)",
          {}};
}

// ----- inverse kinematics -----

TaskStatus probe_chain(std::string id, std::string name, const SkeletonTasks& t) {
  if (!t.ik_chain) return missing(std::move(id), std::move(name));
  const std::vector<int> chain = t.ik_chain(probe_skeleton(), 0, 1);
  return {std::move(id),
          std::move(name),
          !chain.empty(),
          "the chain from the root to bone a has " + std::to_string(chain.size()) + " bones",
          {}};
}

// Bone a's frames at rest: R = I, from the origin to (0, 1, 0).
skeleton::BoneFrames rest_frames() {
  skeleton::BoneFrames f;
  f.rotation = {skeleton::Mat3::Identity(), skeleton::Mat3::Identity()};
  f.start = {Vec3::Zero(), Vec3::Zero()};
  f.end = {Vec3::Zero(), Vec3(0.0, 1.0, 0.0)};
  return f;
}

TaskStatus probe_jacobian(std::string id, std::string name, const SkeletonTasks& t) {
  if (!t.ik_jacobian) return missing(std::move(id), std::move(name));
  skeleton::Matrix3X J;
  t.ik_jacobian(probe_skeleton(), rest_frames(), {1}, J);
  const bool stub = J.size() > 0 && J.isZero(0.0);
  return {std::move(id),
          std::move(name),
          !stub,
          stub ? "J of bone a at rest is zero" : "J of bone a at rest is not zero",
          {}};
}

TaskStatus probe_least_squares(std::string id, std::string name, const SkeletonTasks& t) {
  if (!t.least_squares) return missing(std::move(id), std::move(name));
  skeleton::VectorX x;
  t.least_squares(skeleton::Matrix3X::Identity(3, 3), Vec3(1.0, 2.0, 3.0), x);
  const bool stub = x.size() > 0 && x.isZero(0.0);
  return {std::move(id),
          std::move(name),
          !stub,
          stub ? "x = 0 for J = I and e = (1, 2, 3)" : "x ≠ 0 for J = I and e = (1, 2, 3)",
          {}};
}

// Collaborators that answer at once: the end effector 1 away from the target, J = I, x = e.
skeleton::IkOps probe_ops() {
  skeleton::IkOps ops;
  ops.end_effector = [](const Posture&) { return Vec3(Vec3::Zero()); };
  ops.jacobian = [](const Posture&, skeleton::Matrix3X& J) {
    J = skeleton::Matrix3X::Identity(3, 3);
  };
  ops.solve = [](const skeleton::Matrix3X&, const Vec3& e, skeleton::VectorX& x) { x = e; };
  ops.clamp = [](Posture&) {};
  ops.iterate = [](Posture&) {
    skeleton::IkResult r;
    r.updates = 2;
    r.error = 0.0;
    return r;
  };
  return ops;
}

std::string result_text(const skeleton::IkResult& r) {
  return std::to_string(r.updates) + " updates, error " + format_double(r.error);
}

TaskStatus probe_iterate(std::string id, std::string name, const SkeletonTasks& t) {
  if (!t.ik_iterate) return missing(std::move(id), std::move(name));
  skeleton::IkSettings settings;
  settings.max_iterations = 1;
  Posture p = probe_posture(Vec3::Zero(), Vec3::Zero());
  const skeleton::IkResult r =
      t.ik_iterate(probe_skeleton(), {1}, Vec3(1.0, 0.0, 0.0), settings, probe_ops(), p);
  return {std::move(id),
          std::move(name),
          r.updates != 0 || std::isfinite(r.error),
          "one allowed update towards a target 1 away: " + result_text(r),
          {}};
}

TaskStatus probe_solve(std::string id, std::string name, const SkeletonTasks& t) {
  if (!t.ik_solve) return missing(std::move(id), std::move(name));
  Posture p = probe_posture(Vec3::Zero(), Vec3::Zero());
  const skeleton::IkResult r = t.ik_solve(skeleton::IkSettings{}, probe_ops(), p);
  return {
      std::move(id),
      std::move(name),
      r.stable || std::isfinite(r.error),
      std::string(r.stable ? "stable" : "not stable") + " after an iteration of " + result_text(r),
      {}};
}

}  // namespace

std::vector<std::string_view> skeleton_probe_slots() {
  return {
      "local_rotation", "forward_kinematics", "time_map",      "warped_posture", "blend_motions",
      "ik_chain",       "ik_jacobian",        "least_squares", "ik_iterate",     "ik_solve"};
}

TaskStatus probe_skeleton_slot(std::string_view slot, std::string id, std::string name,
                               const TaskTable& t) {
  const SkeletonTasks& k = skeleton_tasks(t);
  if (slot == "local_rotation") return probe_local_rotation(std::move(id), std::move(name), k);
  if (slot == "forward_kinematics")
    return probe_forward_kinematics(std::move(id), std::move(name), k);
  if (slot == "time_map") return probe_time_map(std::move(id), std::move(name), k);
  if (slot == "warped_posture") return probe_warped_posture(std::move(id), std::move(name), k);
  if (slot == "ik_chain") return probe_chain(std::move(id), std::move(name), k);
  if (slot == "ik_jacobian") return probe_jacobian(std::move(id), std::move(name), k);
  if (slot == "least_squares") return probe_least_squares(std::move(id), std::move(name), k);
  if (slot == "ik_iterate") return probe_iterate(std::move(id), std::move(name), k);
  if (slot == "ik_solve") return probe_solve(std::move(id), std::move(name), k);
  return probe_blend(std::move(id), std::move(name), k);
}

}  // namespace jelly::bodies
