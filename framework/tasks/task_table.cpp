// Builds the TaskTable of the task library this file is compiled into (assignments/, solutions/
// or a submission). Part of the framework: students do not edit it.
#include "jelly/task_table.hpp"
#include "jelly/tasks/collision.hpp"
#include "jelly/tasks/contact.hpp"
#include "jelly/tasks/forces.hpp"
#include "jelly/tasks/integrators.hpp"
#include "jelly/tasks/spring_groups.hpp"
#include "jelly/tasks/springs.hpp"

#ifndef JELLY_TASKS_ORIGIN
#define JELLY_TASKS_ORIGIN "unknown"
#endif

namespace jelly {

TaskTable linked_tasks() {
  TaskTable t;
  t.add_structural_springs = &tasks::add_structural_springs;
  t.add_shear_springs = &tasks::add_shear_springs;
  t.add_bending_springs = &tasks::add_bending_springs;
  t.spring_force = &tasks::spring_force;
  t.damper_force = &tasks::damper_force;
  t.accumulate_spring_forces = &tasks::accumulate_spring_forces;
#ifdef JELLY_TASKS_SPRING_GROUPS  // set by the build for a library that provides it (the reference)
  t.make_spring_group_pass = &tasks::make_spring_group_pass;
#endif
  t.collide_plane = &tasks::collide_plane;
  t.collide_bowl = &tasks::collide_bowl;
  t.contact_plane = &tasks::contact_plane;
  t.contact_bowl = &tasks::contact_bowl;
  t.explicit_euler_step = &tasks::explicit_euler_step;
  t.implicit_euler_step = &tasks::implicit_euler_step;
  t.midpoint_step = &tasks::midpoint_step;
  t.rk4_step = &tasks::rk4_step;
  t.origin = JELLY_TASKS_ORIGIN;
  return t;
}

}  // namespace jelly
