// Slot-level cases of the mass_spring task module (solutions/tasks/mass_spring/): the generators
// that run one case of the spring_force, damper_force and integrator slots of the TaskTable,
// keyed by slot, not by assignment. Every assignment whose manifest lists the module registers
// them from its own assignments/<id>/grader/runner/ and keeps its own case files
// (grader/cases/*.toml), with its own task IDs; what differs between assignments (the free fall's
// start) is a parameter of the registration. docs/new-assignment.md, "Task modules".
#pragma once

#include <string>

#include "harness.hpp"
#include "jelly/task_table.hpp"

namespace jelly::grade {

/// Generators "spring_force" and "damper_force": the student's function on hand-made
/// (params.springs / params.dampers) or random (params.random) inputs; output fNN is the force on
/// particle a of input NN.
void register_spring_force_cases(Registry& r);

/// One course integrator, by params.method.
struct IntegratorMethod {
  const char* key;   // params.method
  const char* name;  // the student's function
  StepFunction TaskTable::*member;
};

/// The integrator params.method names (explicit_euler, implicit_euler, midpoint or rk4); throws
/// naming the key otherwise.
const IntegratorMethod& integrator_method(const Params& params);

/// n steps of h of `fn` on `system` from `s`, with a workspace sized for the system.
void step_n(StepFunction fn, System& system, State& s, double h, long n);

/// Where the free fall's three particles start (3 × 3, one particle a column), and what particle
/// 0 is, as the height output describes it ("a particle dropped from rest at y = 11 m").
struct FreeFallStart {
  Vec3Array x, v;
  std::string dropped;
};

/// Generator "integrator_free_fall": params.steps steps of params.h of the integrator
/// params.method on three particles in free fall from `start`.
void register_integrator_free_fall(Registry& r, const FreeFallStart& start);

/// Generator "integrator_convergence": the integrator params.method's observed order of accuracy
/// on the linear two-particle spring, damping params.damping, one run to t = 1 s per step size in
/// params.h (at least two).
void register_integrator_convergence(Registry& r);

}  // namespace jelly::grade
