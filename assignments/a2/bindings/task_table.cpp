// A2's bindings: fills the framework's TaskTable slots with A2's task functions, for the task
// library this file is compiled into (the stubs, the reference or a submission). Part of the
// framework: students do not edit it.
#include "jelly/a2/task_table.hpp"
#include "jelly/cloth_tasks.hpp"

#include "jelly/a2/collision.hpp"
#include "jelly/a2/forces.hpp"
#include "jelly/a2/friction.hpp"
#include "jelly/a2/integrators.hpp"
#include "jelly/a2/springs.hpp"

#ifndef JELLY_TASKS_ORIGIN
#define JELLY_TASKS_ORIGIN "unknown"
#endif

namespace jelly::a2 {

TaskTable task_table() {
  TaskTable t;
  cloth_tasks(t).add_grid_structural_springs = &add_structural_springs;
  cloth_tasks(t).add_grid_shear_springs = &add_shear_springs;
  cloth_tasks(t).add_grid_bending_springs = &add_bending_springs;
  t.spring_force = &spring_force;
  t.damper_force = &damper_force;
  cloth_tasks(t).collide_particle_sphere = &collide_particle_sphere;
  cloth_tasks(t).collide_spheres = &collide_spheres;
  cloth_tasks(t).friction_impulse = &friction_impulse;
  t.explicit_euler_step = &explicit_euler_step;
  t.implicit_euler_step = &implicit_euler_step;
  t.midpoint_step = &midpoint_step;
  t.rk4_step = &rk4_step;
  add_library_slots(t);
  t.origin = JELLY_TASKS_ORIGIN;
  return t;
}

}  // namespace jelly::a2
