// Kinematic spheres' velocity schedules (cloth contract §3, decision 5).
#include "jelly/spheres.hpp"

namespace jelly {

Vec3 scheduled_velocity(const std::vector<ScheduleEntry>& schedule, long step, double h) {
  // t_n = n·h as a product (never a running sum); an entry applies from the first step whose start
  // is within 1e-6·h after its time, so that an entry at 0.5 s starts at step 5000 of h = 1e-4
  // whatever the rounding of 5000·1e-4.
  const double limit = static_cast<double>(step) * h + 1e-6 * h;
  Vec3 velocity = Vec3::Zero();  // before the first entry: at rest
  for (const ScheduleEntry& e : schedule) {
    if (!(e.time <= limit)) break;  // times increase strictly (checked where a scene is read)
    velocity = e.velocity;
  }
  return velocity;
}

}  // namespace jelly
