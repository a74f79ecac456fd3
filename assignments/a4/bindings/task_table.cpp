// A4's bindings: fills the skeleton's TaskTable slots with A4's task functions, for the task
// library this file is compiled into (the stubs, the reference or a submission). Part of the
// framework: students do not edit it.
#include "jelly/a4/task_table.hpp"
#include "jelly/skeleton_tasks.hpp"

#include "jelly/a4/chain.hpp"
#include "jelly/a4/ik.hpp"
#include "jelly/a4/jacobian.hpp"
#include "jelly/a4/kinematics.hpp"
#include "jelly/a4/least_squares.hpp"

#ifndef JELLY_TASKS_ORIGIN
#define JELLY_TASKS_ORIGIN "unknown"
#endif

namespace jelly::a4 {

TaskTable task_table() {
  TaskTable t;
  SkeletonTasks& k = skeleton_tasks(t);
  k.local_rotation = &local_rotation;
  k.forward_kinematics = &forward_kinematics;
  k.ik_chain = &ik_chain;
  k.ik_jacobian = &ik_jacobian;
  k.least_squares = &least_squares;
  k.ik_iterate = &ik_iterate;
  k.clamp_to_limits = &clamp_to_limits;
  k.ik_solve = &ik_solve;
  add_library_slots(t);
  t.origin = JELLY_TASKS_ORIGIN;
  return t;
}

}  // namespace jelly::a4
