// The viewer's clock: maps wall time to simulated time.
#pragma once

namespace jelly::session {

/// Maps wall time to simulated time: each frame asks for factor × wall time more, the runs step
/// towards it within a wall-time budget, and what they could not do is dropped (no spiral of
/// death) and reported: "can't keep up: running at 0.37× real time".
class RealTimeClock {
 public:
  double factor = 1.0;       ///< real-time factor, 0.1–4
  double budget_ms = 40.0;   ///< wall time per frame the simulation may take [ms]
  double max_frame_s = 0.1;  ///< longer frames (window dragged, debugger) count as this [s]

  static constexpr double kMinFactor = 0.1;
  static constexpr double kMaxFactor = 4.0;

  /// Simulated time the runs should reach this frame, given their current time and the wall
  /// time since the last frame [s].
  double target(double sim_time, double wall_dt);
  /// Reports where the (slowest) run got to and whether a run stopped at its wall-time budget
  /// short of the target; updates the achieved factor and behind().
  void reached(double sim_time_before, double sim_time_after, bool budget_hit);
  /// Whether the runs fell short of real time recently (over the last ~second).
  bool behind() const { return behind_; }
  /// Simulated seconds per wall second, smoothed over about a second.
  double achieved_factor() const { return achieved_; }
  /// Forget the history (after pause, reset or a setting change).
  void restart();

 private:
  double wall_dt_ = 0.0;
  double target_ = 0.0;  // simulated time asked for so far [s]
  double achieved_ = 1.0;
  double short_frames_ = 0.0;  // smoothed fraction of frames that fell short
  bool behind_ = false;
  bool fresh_ = true;
};

}  // namespace jelly::session
