// The grader's child processes go through the one launcher of the framework
// (jelly/process/process.hpp): its names, in the grader's namespace.
#pragma once

#include <jelly/process/process.hpp>

namespace jelly::grade {

using process::ChildResult;
using process::describe_signal;
using process::find_on_path;
using process::Limits;
using process::run_child;
using process::trusted_tool_limits;

}  // namespace jelly::grade
