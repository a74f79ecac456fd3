// A3's case generators (grader/runner/harness.hpp) and the skeletons and motions they feed the
// tasks: the course's files (read by the reference when the data is generated, stored as the
// case's input) or random ones made from the case's parameters.
#pragma once

#include <string>
#include <vector>

#include "harness.hpp"
#include "jelly/skeleton/skeleton.hpp"
#include "jelly/skeleton_tasks.hpp"

namespace jelly::grade {

void register_kinematics_cases(Registry& r);  // A3.T1, A3.T2
void register_warp_cases(Registry& r);        // A3.T3, A3.T4
void register_blend_cases(Registry& r);       // A3.B1

// ----- inputs (skeleton_inputs.cpp) -----

/// What a case plays on: a skeleton and one or two motions.
struct SkeletonInput {
  skeleton::Skeleton skeleton;
  skeleton::Motion motion;    ///< the postures (FK), the input motion (T4), motion A (blend)
  skeleton::Motion motion_b;  ///< motion B of a blend
  std::string words;          ///< what it is, for the outputs' notes
};

/// At generate-reference time: params.course = { asf, amc, from, to, amc_b, from_b, to_b } (files
/// of data/mocap/, frames [from, to) of each motion; scale from params.scale, default 0.2) read
/// into `input`; nothing for a random case.
void prepare_skeleton_input(const Params& params, Json& input);

/// The case's skeleton and motions: the prepared course files, or params.random = { seed, bones,
/// frames, frames_b, scale, angle, translation, near, gimbal } (a random tree, random axes,
/// directions, lengths and dof orders; random postures, frames `near` degrees apart when given,
/// every ry at ±90° with gimbal = 1).
SkeletonInput skeleton_input(const Params& params, const Json& input);

/// The angles' rotations E(θ) (the framework's), one per bone: a posture's rotations compared as
/// rotations, never as Euler triples.
std::vector<skeleton::Mat3> posture_rotations(const std::vector<Vec3>& angles);
/// Emits `prefix`_axis_x, _axis_y, _axis_z: every bone's rotated x, y and z axes (the rotations'
/// columns); the cases' `element = "bone"` names a column "[bone i, x]" in the report. `what` says
/// whose rotations.
void emit_rotations(Outputs& out, const std::string& prefix,
                    const std::vector<skeleton::Mat3>& rotations, const std::string& what);
/// "root, lhipjoint, lfemur, …" (bones in file order) for notes.
std::string bone_list(const skeleton::Skeleton& s);

}  // namespace jelly::grade
