#include "jelly/session/real_time_clock.hpp"

#include <algorithm>

namespace jelly::session {

double RealTimeClock::target(double sim_time, double wall_dt) {
  factor = std::clamp(factor, kMinFactor, kMaxFactor);
  wall_dt_ = std::clamp(wall_dt, 0.0, max_frame_s);
  // The accumulator: the target advances by factor × wall time from the previous target, not
  // from where the run stopped, so rounding to whole steps never accumulates.
  if (fresh_ || sim_time > target_ + 1.0 || sim_time < target_ - 1.0) target_ = sim_time;
  target_ += factor * wall_dt_;
  return target_;
}

void RealTimeClock::reached(double before, double after, bool budget_hit) {
  if (wall_dt_ <= 0.0) return;
  const double rate = (after - before) / wall_dt_;
  // Smooth over about a second of 60 Hz frames.
  achieved_ = fresh_ ? rate : 0.95 * achieved_ + 0.05 * rate;
  fresh_ = false;
  short_frames_ = 0.95 * short_frames_ + 0.05 * (budget_hit ? 1.0 : 0.0);
  behind_ = short_frames_ > 0.3;
  if (budget_hit) target_ = after;  // drop what could not be done: no spiral of death
}

void RealTimeClock::restart() {
  fresh_ = true;
  short_frames_ = 0.0;
  behind_ = false;
  achieved_ = factor;
}

}  // namespace jelly::session
