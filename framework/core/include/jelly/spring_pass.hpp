// The framework's spring pass: applies an assignment's spring and damper force functions to every
// spring of a group. Provided code, not a task: it used to sit in the student's forces.cpp.
#pragma once

#include "jelly/spring.hpp"
#include "jelly/types.hpp"

namespace jelly {

/// The force of one spring (or one damper) on its particle a [N]; the force on b is its negative.
using SpringForceFunction = Vec3 (*)(const Vec3& xa, const Vec3& xb, double ks, double rest_length,
                                     double degenerate_length);
using DamperForceFunction = Vec3 (*)(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb,
                                     double kd, double degenerate_length);

/// Adds spring_force + damper_force of every spring of `group` at state `s` to `f` (3×N [N]):
/// f_a += f, f_b −= f, spring by spring in the group's order (the sums of contract §2).
void accumulate_spring_forces(const SpringGroup& group, const State& s, Vec3Array& f,
                              SpringForceFunction spring_force, DamperForceFunction damper_force);

}  // namespace jelly
