// jelly-lab's stepping: the Simulator's fixed step, driven by the clock (never in a draw call).
#include <algorithm>

#include "app_loop.hpp"

namespace jelly::app {

using session::SimulationRun;

bool advance_runs(AppState& s, const AppOptions& opt, SmokeScript& script, double wall_dt,
                  int frame_number) {
  if (opt.smoke_test) return script.frame(s, !opt.screenshot.empty());
  const std::vector<SimulationRun*> runs = s.run_pointers();
  if (opt.shot_at >= 0.0) {
    for (SimulationRun* r : runs) r->advance_to(opt.shot_at);
    if (frame_number > 4) {  // a few frames so ImGui's layout settles
      s.screenshot_requested = true;
      return true;
    }
  } else if (s.recording) {
    // Recording: a fixed 1/30 s × factor per frame, so the video plays at the chosen speed.
    const double t = runs.front()->time() + s.clock.factor / 30.0;
    for (SimulationRun* r : runs) r->advance_to(t);
  } else if (s.playing && opt.benchmark == 0) {
    double before = runs.front()->time();
    for (SimulationRun* r : runs) before = std::min(before, r->time());
    const double target = s.clock.target(before, wall_dt);
    const double budget = s.clock.budget_ms / static_cast<double>(runs.size());
    bool hit = false;
    double after = target;
    for (SimulationRun* r : runs) {
      r->advance_to(target, budget);
      hit = hit || r->budget_hit();
      if (!r->unstable() && r->ok()) after = std::min(after, r->time());
    }
    s.clock.reached(before, after, hit);
  }
  return false;
}

void apply_single_step(AppState& s) {
  if (!s.step_requested) return;
  for (SimulationRun* r : s.run_pointers()) r->step_once();
  s.step_requested = false;
  s.playing = false;
}

}  // namespace jelly::app
