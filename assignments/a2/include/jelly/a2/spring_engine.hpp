// The reference's spring engine for A2 (solutions/a2/spring_engine.cpp, which compiles A1's
// engine in this namespace): a spring pass over every group at once. Not a task; only the
// reference defines it, and only its task table uses it.
#pragma once

#include <memory>

#include "jelly/spring_group_pass.hpp"

namespace jelly::a2 {

std::unique_ptr<SpringGroupPass> make_spring_group_pass();

}  // namespace jelly::a2
