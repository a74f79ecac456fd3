// What every body kind does with the springs a student's builder returned, before they reach the
// force pass: the framework never trusts a builder's output blindly (a bad index would crash it).
#pragma once

#include "jelly/spring.hpp"

namespace jelly {

/// Throws std::runtime_error naming `builder` and the first spring of `group` that does not join
/// two different particles in [lo, hi) with a finite rest length ≥ 0.
void check_built_springs(const SpringGroup& group, int lo, int hi, const char* builder);

}  // namespace jelly
