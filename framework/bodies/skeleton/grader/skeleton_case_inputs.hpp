// The skeletons and postures the grader's cases of the skeleton's slots (jelly/skeleton_tasks.hpp)
// play on, for every assignment that has such tasks: the course's files (data/mocap/, read by the
// reference when the data is generated and stored as the case's input, so that grading reads no
// file) or random ones made from the case's parameters; and their JSON, as a case's input records
// them. An assignment's runner (assignments/<id>/grader/runner/) uses them with its own case
// files; docs/new-assignment.md, "Shared tasks, shared case code".
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "harness.hpp"
#include "jelly/skeleton/skeleton.hpp"
#include "jelly/skeleton_tasks.hpp"

namespace jelly::grade {

/// What a case plays on: a skeleton and one or two motions.
struct SkeletonInput {
  skeleton::Skeleton skeleton;
  skeleton::Motion motion;  ///< the postures (FK, IK), the input motion (a warp), motion A (blend)
  skeleton::Motion motion_b;  ///< motion B of a blend
  std::string words;          ///< what it is, for the outputs' notes
};

/// Whether the course skeleton's joint limits (the ASF's `limits`) go into a case's
/// input: an assignment whose tasks clamp to them records them; one whose tasks use none
/// leaves them out, and its skeletons have none.
enum class LimitsInInput { Omitted, Recorded };

/// At generate-reference time: params.course = { asf, amc?, from?, to?, amc_b?, from_b?, to_b? }
/// (files of data/mocap/, frames [from, to) of each motion, none without amc; scale from
/// params.scale, default 0.2) read into `input`; nothing for a random case.
void prepare_skeleton_input(const Params& params, Json& input, LimitsInInput limits);

/// The case's skeleton and motions: the prepared course files, or params.random = { seed, bones,
/// frames, frames_b, scale, angle, translation, near, gimbal, limits } (a random tree, random
/// axes, directions, lengths and dof orders; random postures, frames `near` degrees apart when
/// given, every ry at ±90° with gimbal = 1; with limits = 1 random limits on about two bones in
/// three, 2: the root's too).
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

/// Every bone's angles (3×n, column b = (rx, ry, rz) of bone b).
Vec3Array posture_angles(const skeleton::Posture& p);

/// The angles' rotations E(θ) (the framework's), one per bone: a posture's rotations compared as
/// rotations, never as Euler triples.
std::vector<skeleton::Mat3> posture_rotations(const std::vector<Vec3>& angles);
/// Emits `prefix`_axis_x, _axis_y, _axis_z: every bone's rotated x, y and z axes (the rotations'
/// columns); the cases' `element = "bone"` names a column "[bone i, x]" in the report. `what` says
/// whose rotations.
void emit_rotations(Outputs& out, const std::string& prefix,
                    const std::vector<skeleton::Mat3>& rotations, const std::string& what);
/// "0 root, 1 lhipjoint, …" (bones in file order, at most 40) for notes.
std::string bone_list(const skeleton::Skeleton& s);

}  // namespace jelly::grade
