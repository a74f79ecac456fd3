// Probes each student task once on a tiny input (see task_probe.hpp).
#include "jelly/task_probe.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "jelly/body_kind.hpp"
#include "jelly/test_systems.hpp"

namespace jelly {

namespace {

TaskStatus probe_integrator(std::string id, std::string name, StepFunction fn) {
  TaskStatus st{std::move(id), std::move(name), false, "function missing from the task table", {}};
  if (!fn) return st;
  // One particle at rest under gravity: any integrator moves it within one step of 0.01 s.
  FreeFallSystem system(1, Vec3(0.0, -9.8, 0.0));
  State s;
  s.resize(1);
  s.x.setZero();
  s.v.setZero();
  const State before = s;
  Workspace w;
  w.resize(1);
  fn(system, s, 0.01, w);
  const bool changed =
      !(s.x.array() == before.x.array()).all() || !(s.v.array() == before.v.array()).all();
  st.implemented = changed;
  st.evidence = changed ? "a falling particle moved in one step"
                        : "one step under gravity left the state unchanged";
  return st;
}

// A particle just above the plane y = 0 and the bottom of the probe's bowl: φ = 0.001 < ε for both.
const Vec3 kNearBottom(0.0, 0.001, 0.0);

// The collision slots: a particle moving into the terrain must respond (return true or change v).
template <typename Shape>
TaskStatus probe_collision(std::string id, std::string name,
                           bool (*fn)(const Shape&, const Vec3&, Vec3&), const Shape& shape,
                           const std::string& terrain) {
  TaskStatus st{std::move(id), std::move(name), false, "function missing from the task table", {}};
  if (!fn) return st;
  const Vec3 incoming(0.0, -1.0, 0.0);
  Vec3 v = incoming;
  st.implemented = fn(shape, kNearBottom, v) || v != incoming;
  st.evidence = st.implemented ? "a particle moving into the " + terrain + " responded"
                               : "a particle moving into the " + terrain + " did not collide";
  return st;
}

// How the contact evidence names the particle's place: resting on/in, pressed onto/into.
struct ContactWords {
  const char* resting;
  const char* pressed;
};

// The contact slots: a particle pressed onto the terrain must get a contact force (return true or
// change f).
template <typename Shape>
TaskStatus probe_contact(std::string id, std::string name,
                         bool (*fn)(const Shape&, const Vec3&, const Vec3&, Vec3&),
                         const Shape& shape, ContactWords words) {
  TaskStatus st{std::move(id), std::move(name), false, "function missing from the task table", {}};
  if (!fn) return st;
  const Vec3 pressing(0.0, -10.0, 0.0);
  Vec3 f = pressing;
  st.implemented = fn(shape, kNearBottom, Vec3::Zero(), f) || f != pressing;
  st.evidence = st.implemented
                    ? "a particle " + std::string(words.resting) + " got a contact force"
                    : "a particle " + std::string(words.pressed) + " got no contact force";
  return st;
}

TaskStatus probe_spring_force(std::string id, std::string name, const TaskTable& t) {
  // A spring stretched from rest length 1 to 2 pulls its ends together.
  TaskStatus st{std::move(id), std::move(name), false, "function missing from the task table", {}};
  if (!t.spring_force) return st;
  const Vec3 f = t.spring_force(Vec3::Zero(), Vec3(2.0, 0.0, 0.0), 10.0, 1.0, 1e-9);
  st.implemented = !f.isZero(0.0);
  st.evidence = st.implemented ? "a stretched spring pulls" : "a stretched spring gave zero force";
  return st;
}

TaskStatus probe_damper_force(std::string id, std::string name, const TaskTable& t) {
  // Ends separating along the spring are damped.
  TaskStatus st{std::move(id), std::move(name), false, "function missing from the task table", {}};
  if (!t.damper_force) return st;
  const Vec3 f = t.damper_force(Vec3::Zero(), Vec3(1.0, 0.0, 0.0), Vec3(-1.0, 0.0, 0.0),
                                Vec3(1.0, 0.0, 0.0), 5.0, 1e-9);
  st.implemented = !f.isZero(0.0);
  st.evidence =
      st.implemented ? "separating ends are damped" : "separating ends gave zero damping force";
  return st;
}

Plane probe_plane() { return Plane{}; }  // y = 0, normal +y, no hole, ε = 0.01

Bowl probe_bowl() {  // centre (0, 1, 0), R = 1, rim at y = 1: a hemisphere whose bottom is the
                     // origin
  Bowl bowl;
  bowl.center = Vec3(0.0, 1.0, 0.0);
  bowl.radius = 1.0;
  bowl.rim_height = 1.0;
  return bowl;
}

}  // namespace

std::vector<std::string_view> probe_slots() {
  std::vector<std::string_view> slots = {
      "spring_force",  "damper_force", "collide_plane",       "collide_bowl",
      "contact_plane", "contact_bowl", "explicit_euler_step", "implicit_euler_step",
      "midpoint_step", "rk4_step"};
  // Then the slots that take a body kind's own types (its lattice or grid, its bodies).
  for (const BodyKindModule* kind : body_kinds())
    for (std::string_view slot : kind->probe_slots()) slots.push_back(slot);
  return slots;
}

TaskStatus probe_slot(std::string_view slot, std::string id, std::string name, const TaskTable& t) {
  if (slot == "spring_force") return probe_spring_force(std::move(id), std::move(name), t);
  if (slot == "damper_force") return probe_damper_force(std::move(id), std::move(name), t);
  if (slot == "collide_plane")
    return probe_collision(std::move(id), std::move(name), t.collide_plane, probe_plane(), "plane");
  if (slot == "collide_bowl")
    return probe_collision(std::move(id), std::move(name), t.collide_bowl, probe_bowl(), "bowl");
  if (slot == "contact_plane")
    return probe_contact(std::move(id), std::move(name), t.contact_plane, probe_plane(),
                         {"resting on the plane", "pressed onto the plane"});
  if (slot == "contact_bowl")
    return probe_contact(std::move(id), std::move(name), t.contact_bowl, probe_bowl(),
                         {"resting in the bowl", "pressed into the bowl"});
  if (slot == "explicit_euler_step")
    return probe_integrator(std::move(id), std::move(name), t.explicit_euler_step);
  if (slot == "implicit_euler_step")
    return probe_integrator(std::move(id), std::move(name), t.implicit_euler_step);
  if (slot == "midpoint_step")
    return probe_integrator(std::move(id), std::move(name), t.midpoint_step);
  if (slot == "rk4_step") return probe_integrator(std::move(id), std::move(name), t.rk4_step);
  for (const BodyKindModule* kind : body_kinds()) {
    const std::vector<std::string_view> own = kind->probe_slots();
    if (std::find(own.begin(), own.end(), slot) != own.end())
      return kind->probe_slot(slot, std::move(id), std::move(name), t);
  }
  throw std::invalid_argument("task " + id + ": probe: expected one of the framework's slots " +
                              "(jelly/task_probe.hpp), not \"" + std::string(slot) + "\"");
}

std::vector<TaskStatus> probe_tasks(const AssignmentManifest& manifest, const TaskTable& t) {
  std::vector<TaskStatus> out;
  for (const ManifestTask& task : manifest.tasks)
    if (!task.probe.empty()) {
      out.push_back(probe_slot(task.probe, task.id, task.short_name, t));
      out.back().slot = task.probe;
    }
  return out;
}

std::vector<std::string> missing_task_ids(const std::vector<TaskStatus>& statuses) {
  std::vector<std::string> ids;
  for (const TaskStatus& s : statuses)
    if (!s.implemented) ids.push_back(s.id);
  return ids;
}

}  // namespace jelly
