// The one narrow interface between the framework and an assignment's student tasks: the core's
// seams.
//
// The core never calls a task function by name: it calls through a TaskTable, whose slots are
// named after what the physics needs (build the springs of a lattice, the force of one spring,
// one integrator step, ...), never after an assignment's task IDs. An assignment fills the slots
// its tasks implement (assignments/<id>/bindings/task_table.cpp, the function
// jelly::<namespace>::task_table()); its manifest (assignment.toml) says which task fills which
// slot. Slots an assignment does not fill stay null, and the effects that need them are off.
// Tests wrap a table to count calls.
#pragma once

#include <cstddef>
#include <memory>
#include <string_view>
#include <vector>

#include "jelly/kind_parts.hpp"
#include "jelly/spring.hpp"
#include "jelly/spring_group_pass.hpp"
#include "jelly/system.hpp"
#include "jelly/terrain.hpp"

namespace jelly {

/// Signature shared by the integrator slots (and the framework's symplectic Euler).
using StepFunction = void (*)(System& system, State& s, double h, Workspace& w);

struct TaskTable {
  // The force of one spring and one damper on its particle a; the framework applies them to a
  // spring group (jelly/spring_pass.hpp).
  Vec3 (*spring_force)(const Vec3&, const Vec3&, double, double, double) = nullptr;
  Vec3 (*damper_force)(const Vec3&, const Vec3&, const Vec3&, const Vec3&, double,
                       double) = nullptr;
  /// Optional (nullptr unless the library provides it; the reference does): makes a spring
  /// engine that does every group in one call (jelly/spring_group_pass.hpp). A World makes one
  /// when this is set and uses it instead of the framework's group-by-group pass.
  std::unique_ptr<SpringGroupPass> (*make_spring_group_pass)() = nullptr;
  // Collision response against the terrain (contract §4).
  bool (*collide_plane)(const Plane&, const Vec3&, Vec3&) = nullptr;
  bool (*collide_bowl)(const Bowl&, const Vec3&, Vec3&) = nullptr;
  // Contact and friction forces (contract §5).
  bool (*contact_plane)(const Plane&, const Vec3&, const Vec3&, Vec3&) = nullptr;
  bool (*contact_bowl)(const Bowl&, const Vec3&, const Vec3&, Vec3&) = nullptr;
  // The course's four integrators (contract §6).
  StepFunction explicit_euler_step = nullptr;
  StepFunction implicit_euler_step = nullptr;
  StepFunction midpoint_step = nullptr;
  StepFunction rk4_step = nullptr;

  /// The slots that take a body kind's own types (its lattice or grid, its bodies), one struct per
  /// kind, declared and reached through the kind's header (framework/bodies/<kind>/include/jelly/
  /// <kind>_tasks.hpp). Filled by the bindings like the slots above; all null by default.
  KindParts kinds;

  /// Where the table's functions come from: "assignments", "solutions" or "submission".
  std::string_view origin;
};

}  // namespace jelly
