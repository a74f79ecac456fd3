// An optional entry point a task library may provide: the spring pass over all of a world's spring
// groups at once. Not a task: students never write it. The reference provides it so that one
// evaluation turns the state into structure-of-arrays once (not once per group) and runs one
// parallel region; without it the framework calls accumulate_spring_forces group by group.
#pragma once

#include <cstddef>

#include "jelly/spring.hpp"
#include "jelly/types.hpp"

namespace jelly::tasks {

/// Adds the spring and damper forces of groups[0 … count−1] at state `s` to `f` (3×N [N]).
/// Must give the same bits as calling accumulate_spring_forces on each group in turn.
void accumulate_spring_groups(const SpringGroup* groups, std::size_t count, const State& s,
                              Vec3Array& f);

}  // namespace jelly::tasks
