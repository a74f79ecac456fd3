// jelly-lab --smoke-test: a scripted, reproducible tour of every integrator and every scene.
#include <algorithm>
#include <cstdio>

#include "app_loop.hpp"

namespace jelly::app {

using session::SimulationRun;

void SmokeScript::begin(AppState& s) {
  s.integrator = integrators_[0];
  s.comparing = false;
  rebuild_runs(s);
}

bool SmokeScript::frame(AppState& s, bool screenshot) {
  const std::vector<SimulationRun*> runs = s.run_pointers();
  if (!scenes_phase_) {
    // 0.25 s of simulated time per frame, no wall clock (reproducible).
    const double t = runs.front()->time() + 0.25;
    runs.front()->advance_to(t);
    if (!runs.front()->ok()) ++failures_;
    if (runs.front()->time() >= 2.0 - 1e-9 || runs.front()->unstable() || !runs.front()->ok()) {
      std::printf("smoke: %-45s t = %.3f s, %ld steps, %.3f ms/step%s\n",
                  std::string(display_name(s.integrator)).c_str(), runs.front()->time(),
                  runs.front()->simulator() ? runs.front()->simulator()->steps() : 0L,
                  runs.front()->ms_per_step(),
                  runs.front()->unstable() ? " (detector stopped it)" : "");
      if (++integrator_ < integrators_.size()) {
        s.integrator = integrators_[integrator_];
      } else {
        scenes_phase_ = true;
        if (!s.scenes.empty() && !load_scene_into(s, 0)) {
          std::printf("smoke: scene %s failed: %s\n", s.scenes[0].name.c_str(),
                      s.scene_error.c_str());
          ++failures_;
        }
      }
      rebuild_runs(s);
    }
    return false;
  }
  if (scene_frames_ == 0) check_body_keys(s);
  for (SimulationRun* r : runs) r->advance_to(r->time() + 0.1);
  if (++scene_frames_ < 3) return false;
  std::printf("smoke: scene %-35s ok, t = %.2f s\n", s.edited.name.c_str(), runs.front()->time());
  scene_frames_ = 0;
  if (++scene_ < s.scenes.size()) {
    if (!load_scene_into(s, static_cast<int>(scene_))) {
      // A scene this program cannot show must say so and leave the viewer as it was.
      std::printf("smoke: scene %s %s: %s\n", s.scenes[scene_].name.c_str(),
                  s.scene_not_shown ? "not shown" : "failed", s.scene_error.c_str());
      if (!s.scene_not_shown) ++failures_;
    }
    return false;
  }
  // Back to the default scene (the assignment's manifest's default_scene, from the scenes folder
  // or built in) for the screenshot, a little after the start.
  const std::string name = session::default_scene_name();
  int start = 0;
  for (std::size_t i = 0; i < s.scenes.size(); ++i)
    if (s.scenes[i].name == name || s.scenes[i].name == "builtin:" + name) {
      start = static_cast<int>(i);
      break;
    }
  load_scene_into(s, start);
  for (SimulationRun* r : s.run_pointers()) r->advance_to(1.5);
  s.screenshot_requested = screenshot;
  return true;
}

void SmokeScript::check_body_keys(AppState& s) {
  const std::vector<const render::BodyView*> shown = shown_views(s);
  for (auto& [view, controls] : s.body_controls)
    if (std::find(shown.begin(), shown.end(), view) != shown.end())
      failures_ += controls->smoke_check(s.viewer_context());
}

}  // namespace jelly::app
