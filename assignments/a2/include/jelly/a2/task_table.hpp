// A2's task table: its task functions in the framework's TaskTable slots (bindings/task_table.cpp),
// for whichever implementation is linked (the stubs, the reference or a submission).
#pragma once

#include "jelly/task_table.hpp"

namespace jelly::a2 {

TaskTable task_table();

}  // namespace jelly::a2
