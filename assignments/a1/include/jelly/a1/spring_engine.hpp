// The reference's spring engine (solutions/a1/spring_engine.cpp): a spring pass over every group
// at once. Not a task; only the reference defines it, and only its task table uses it.
#pragma once

#include <memory>

#include "jelly/spring_group_pass.hpp"

namespace jelly::a1 {

std::unique_ptr<SpringGroupPass> make_spring_group_pass();

}  // namespace jelly::a1
