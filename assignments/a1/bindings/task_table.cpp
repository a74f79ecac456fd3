// A1's bindings: fills the framework's TaskTable slots with A1's task functions, for the task
// library this file is compiled into (the stubs, the reference or a submission). Part of the
// framework: students do not edit it.
#include "jelly/a1/task_table.hpp"
#include "jelly/cube_tasks.hpp"

#include "jelly/a1/collision.hpp"
#include "jelly/a1/contact.hpp"
#include "jelly/a1/forces.hpp"
#include "jelly/a1/integrators.hpp"
#include "jelly/a1/springs.hpp"

#ifndef JELLY_TASKS_ORIGIN
#define JELLY_TASKS_ORIGIN "unknown"
#endif

namespace jelly::a1 {

TaskTable task_table() {
  TaskTable t;
  cube_tasks(t).add_structural_springs = &add_structural_springs;
  cube_tasks(t).add_shear_springs = &add_shear_springs;
  cube_tasks(t).add_bending_springs = &add_bending_springs;
  t.spring_force = &spring_force;
  t.damper_force = &damper_force;
  t.collide_plane = &collide_plane;
  t.collide_bowl = &collide_bowl;
  t.contact_plane = &contact_plane;
  t.contact_bowl = &contact_bowl;
  t.explicit_euler_step = &explicit_euler_step;
  t.implicit_euler_step = &implicit_euler_step;
  t.midpoint_step = &midpoint_step;
  t.rk4_step = &rk4_step;
  add_library_slots(t);
  t.origin = JELLY_TASKS_ORIGIN;
  return t;
}

}  // namespace jelly::a1
