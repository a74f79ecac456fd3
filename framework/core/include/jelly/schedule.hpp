// A schedule of vectors over time, as a scene writes it ("t: x,y,z; t: x,y,z", a value kind of the
// parameter table): for example a kinematic obstacle's velocities.
#pragma once

#include "jelly/types.hpp"

namespace jelly {

/// One entry of a schedule: from `time` on, the value is `velocity`.
struct ScheduleEntry {
  double time = 0.0;             ///< [s]
  Vec3 velocity{0.0, 0.0, 0.0};  ///< [m/s]
};

}  // namespace jelly
