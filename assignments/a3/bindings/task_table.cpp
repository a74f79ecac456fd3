// A3's bindings: fills the skeleton's TaskTable slots with A3's task functions, for the task
// library this file is compiled into (the stubs, the reference or a submission). Part of the
// framework: students do not edit it.
#include "jelly/a3/task_table.hpp"
#include "jelly/skeleton_tasks.hpp"

#include "jelly/a3/blend.hpp"
#include "jelly/a3/kinematics.hpp"
#include "jelly/a3/time_warp.hpp"

#ifndef JELLY_TASKS_ORIGIN
#define JELLY_TASKS_ORIGIN "unknown"
#endif

namespace jelly::a3 {

TaskTable task_table() {
  TaskTable t;
  SkeletonTasks& k = skeleton_tasks(t);
  k.local_rotation = &local_rotation;
  k.forward_kinematics = &forward_kinematics;
  k.time_map = &time_map;
  k.warped_posture = &warped_posture;
  k.blend_motions = &blend_motions;
  add_library_slots(t);
  t.origin = JELLY_TASKS_ORIGIN;
  return t;
}

}  // namespace jelly::a3
