// The one narrow interface between the framework and the student tasks.
//
// The framework never calls a task function by name: it calls through a TaskTable. The table of
// whichever task library is linked (assignments/, solutions/, or a submission the grader built)
// comes from linked_tasks(), defined in that library. Tests wrap a table to count calls.
#pragma once

#include <cstddef>
#include <memory>
#include <string_view>
#include <vector>

#include "jelly/cube.hpp"
#include "jelly/spring.hpp"
#include "jelly/system.hpp"
#include "jelly/tasks/spring_groups.hpp"
#include "jelly/terrain.hpp"

namespace jelly {

/// Signature shared by the four course integrators (and the framework's symplectic Euler).
using StepFunction = void (*)(System& system, State& s, double h, Workspace& w);

struct TaskTable {
  // A1.T1–T3: spring builder
  void (*add_structural_springs)(const CubeLattice&, std::vector<Spring>&) = nullptr;
  void (*add_shear_springs)(const CubeLattice&, std::vector<Spring>&) = nullptr;
  void (*add_bending_springs)(const CubeLattice&, std::vector<Spring>&) = nullptr;
  // A1.T4–T5: forces, and the provided loop that applies them to a spring group
  Vec3 (*spring_force)(const Vec3&, const Vec3&, double, double, double) = nullptr;
  Vec3 (*damper_force)(const Vec3&, const Vec3&, const Vec3&, const Vec3&, double,
                       double) = nullptr;
  void (*accumulate_spring_forces)(const SpringGroup&, const State&, Vec3Array&) = nullptr;
  /// Optional (nullptr unless the library provides it; the reference does): makes a spring
  /// engine that does every group in one call (jelly/tasks/spring_groups.hpp). A World makes one
  /// when this is set and uses it instead of accumulate_spring_forces.
  std::unique_ptr<SpringGroupPass> (*make_spring_group_pass)() = nullptr;
  // A1.T6–T7: collision response
  bool (*collide_plane)(const Plane&, const Vec3&, Vec3&) = nullptr;
  bool (*collide_bowl)(const Bowl&, const Vec3&, Vec3&) = nullptr;
  // A1.T8–T9: contact force
  bool (*contact_plane)(const Plane&, const Vec3&, const Vec3&, Vec3&) = nullptr;
  bool (*contact_bowl)(const Bowl&, const Vec3&, const Vec3&, Vec3&) = nullptr;
  // A1.T10–T13: integrators
  StepFunction explicit_euler_step = nullptr;
  StepFunction implicit_euler_step = nullptr;
  StepFunction midpoint_step = nullptr;
  StepFunction rk4_step = nullptr;

  /// Where the table's functions come from: "assignments", "solutions" or "submission".
  std::string_view origin;
};

/// The table of the task library linked into this binary (defined by that library).
TaskTable linked_tasks();

}  // namespace jelly
