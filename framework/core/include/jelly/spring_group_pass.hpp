// An optional spring engine a task library may provide: the spring pass over all of a world's
// spring groups at once. Not a task: students never write it. The reference provides one
// (solutions/tasks/mass_spring/spring_engine.cpp) so that one evaluation turns the state into
// structure-of-arrays once (not once per group) and runs one parallel region; without it the World
// calls accumulate_spring_forces group by group.
#pragma once

#include <cstddef>
#include <memory>

#include "jelly/spring.hpp"
#include "jelly/types.hpp"

namespace jelly {

/// A spring pass over many groups, with whatever it derives from the springs (layouts, scratch)
/// kept inside it. One World owns one (TaskTable::make_spring_group_pass); it is not shared
/// between threads.
class SpringGroupPass {
 public:
  virtual ~SpringGroupPass() = default;

  /// Adds the spring and damper forces of groups[0 … count−1] at state `s` to `f` (3×N [N]):
  /// spring_force + damper_force of every spring, + on a and − on b, as accumulate_spring_forces
  /// does, the sums possibly taken in another (fixed) order. The bits must not depend on the
  /// number of threads.
  virtual void accumulate(const SpringGroup* groups, std::size_t count, const State& s,
                          Vec3Array& f) = 0;
  /// Lets the pass use up to `threads` threads from now on (at least 1).
  virtual void set_threads(int threads) = 0;
  /// The springs of a group given before have changed (same position, new content): forget
  /// whatever was derived from them. A group whose spring list moved or changed size is noticed
  /// without it.
  virtual void springs_changed() = 0;
};

}  // namespace jelly
