// A4's task table: its task functions in the skeleton's TaskTable slots (bindings/task_table.cpp),
// for whichever implementation is linked (the stubs, the reference or a submission).
#pragma once

#include "jelly/task_table.hpp"

namespace jelly::a4 {

TaskTable task_table();

/// The slots the linked task library fills besides the tasks above (none for the student's code):
/// task_table() calls it. The build defines it for each task library
/// (cmake/JellyAssignments.cmake).
void add_library_slots(TaskTable& t);

}  // namespace jelly::a4
