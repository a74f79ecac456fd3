// A4's case generators (grader/runner/harness.hpp) and the skeletons, postures and recorded
// answers they feed the tasks: the course's files (read by the reference when the data is
// generated, stored as the case's input) or random ones made from the case's parameters. The
// iteration and the solve run through scripted IkOps (ik_script.cpp): answers recorded from the
// reference when the data was generated, or a toy the case describes; never the reference itself,
// which is not linked with a submission.
#pragma once

#include <string>
#include <vector>

#include "harness.hpp"
#include "jelly/skeleton/ik.hpp"
#include "jelly/skeleton/skeleton.hpp"
#include "jelly/skeleton_tasks.hpp"

namespace jelly::grade {

void register_kinematics_cases(Registry& r);     // A4.T0
void register_chain_cases(Registry& r);          // A4.T1
void register_jacobian_cases(Registry& r);       // A4.T2
void register_least_squares_cases(Registry& r);  // A4.T3
void register_iterate_cases(Registry& r);        // A4.T4
void register_limits_cases(Registry& r);         // A4.T5

// ----- inputs (skeleton_inputs.cpp) -----

/// What a case plays on: a skeleton and its postures.
struct SkeletonInput {
  skeleton::Skeleton skeleton;
  skeleton::Motion motion;  ///< the postures
  std::string words;        ///< what it is, for the outputs' notes
};

/// At generate-reference time: params.course = { asf, amc?, from?, to? } (files of data/mocap/,
/// frames [from, to) of the motion, none without amc; scale from params.scale, default 0.2) read
/// into `input`; nothing for a random case.
void prepare_skeleton_input(const Params& params, Json& input);

/// The case's skeleton and postures: the prepared course files, or params.random = { seed, bones,
/// frames, scale, angle, translation, limits } (a random tree, random axes, directions, lengths
/// and dof orders; random postures; with limits = 1 random limits on about two bones in three, 2:
/// the root's too).
SkeletonInput skeleton_input(const Params& params, const Json& input);

/// A bone's index by name ("lowerback") or as a number in a string ("7"); throws naming `key`.
int bone_index(const skeleton::Skeleton& s, const std::string& name, const std::string& key);

/// A posture as [tx, ty, tz, rx0, ry0, rz0, rx1, …] and back.
Json posture_json(const skeleton::Posture& p);
skeleton::Posture json_posture(const Json& j, std::size_t bones);
Json vec_json(const Vec3& v);
Vec3 json_vec(const Json& j);

/// Forward kinematics as recorded in an input: { rotation: [[9 numbers, column by column]…],
/// start: [[x, y, z]…], end: […] }.
Json frames_json(const skeleton::BoneFrames& f);
skeleton::BoneFrames json_frames(const Json& j);

/// Every bone's angles (3×n, column b = (rx, ry, rz) of bone b) and the chain's angles alone.
Vec3Array posture_angles(const skeleton::Posture& p);
Vec3Array chain_angles(const skeleton::Posture& p, const std::vector<int>& chain);

/// The angles' rotations E(θ) (the framework's), one per bone.
std::vector<skeleton::Mat3> posture_rotations(const std::vector<Vec3>& angles);
/// Emits `prefix`_axis_x, _axis_y, _axis_z: every bone's rotated axes (the rotations' columns).
void emit_rotations(Outputs& out, const std::string& prefix,
                    const std::vector<skeleton::Mat3>& rotations, const std::string& what);
/// "0 root, 1 lhipjoint, …" (bones in file order, at most 40) for notes.
std::string bone_list(const skeleton::Skeleton& s);
/// "rfingers ← rwrist ← … ← lowerback" for notes.
std::string chain_text(const skeleton::Skeleton& s, const std::vector<int>& chain);

// ----- scripted collaborators (ik_script.cpp) -----

/// What the iteration's collaborators answer, call after call: recorded from the reference's own
/// solve when the data was generated, or a toy the case describes. Each op answers its k-th call
/// with its k-th answer (the last one past the end) and records what it was given.
struct IkScript {
  std::vector<Vec3> effector;            ///< p of each end_effector call
  std::vector<skeleton::Matrix3X> J;     ///< J of each jacobian call
  std::vector<skeleton::VectorX> x;      ///< x of each solve call
  std::vector<skeleton::Posture> clamp;  ///< the posture each clamp call leaves
};
Json script_json(const IkScript& s);
IkScript json_script(const Json& j, std::size_t bones);

/// What the scripted ops were given.
struct IkLog {
  std::vector<skeleton::Posture> effector;  ///< the posture of each end_effector call
  std::vector<Vec3> e;                      ///< the e of each solve call
  std::vector<skeleton::Posture> clamp;     ///< the posture each clamp call got
  int jacobian_calls = 0;
};

/// Ops that answer from `script` and write into `log` (both outlive the ops).
skeleton::IkOps scripted_ops(const IkScript& script, IkLog& log);

/// The reference's own ops (the tasks of `t`, the reference at generate-reference time) for one
/// chain and target, recording every answer into `script`.
skeleton::IkOps recording_ops(const TaskTable& t, const skeleton::Skeleton& s,
                              const std::vector<int>& chain, IkScript& script);

/// Settings from params.settings = { step, epsilon, max_iterations, limits, restore } (the
/// course's defaults for those it leaves out).
skeleton::IkSettings settings_of(const Params& params);

}  // namespace jelly::grade
