// jelly-lab --smoke-test: a scripted, reproducible tour of every integrator and every scene.
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
  if (scene_frames_ == 0 && has_cloth(s)) check_cloth_keys(s);
  for (SimulationRun* r : runs) r->advance_to(r->time() + 0.1);
  if (++scene_frames_ < 3) return false;
  std::printf("smoke: scene %-35s ok, t = %.2f s\n", s.edited.name.c_str(), runs.front()->time());
  scene_frames_ = 0;
  if (++scene_ < s.scenes.size()) {
    if (!load_scene_into(s, static_cast<int>(scene_))) {
      std::printf("smoke: scene %s failed: %s\n", s.scenes[scene_].name.c_str(),
                  s.scene_error.c_str());
      ++failures_;
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

void SmokeScript::check_cloth_keys(AppState& s) {
  SimulationRun& run = *s.runs.front();
  World& world = run.simulator()->world();
  const ClothGrid& grid = world.cloths().front();
  const auto fail = [&](const std::string& what) {
    std::printf("smoke: scene %s: %s\n", s.edited.name.c_str(), what.c_str());
    ++failures_;
  };
  // Keys 1–4: each corner flips, and flips back.
  for (int corner = 0; corner < 4; ++corner) {
    const int p = session::corner_particle(grid, corner);
    const bool before = world.is_pinned(p);
    toggle_pin(s, corner);
    if (world.is_pinned(p) == before)
      fail("key " + std::to_string(corner + 1) + " did not change the pin of particle " +
           std::to_string(p));
    toggle_pin(s, corner);
    if (world.is_pinned(p) != before)
      fail("key " + std::to_string(corner + 1) + " twice did not restore particle " +
           std::to_string(p));
  }
  std::string arrows;
  if (has_kinematic_sphere(s)) {
    // Right arrow for 0.1 s: the sphere moves speed × 0.1 s along the view's right axis; S stops
    // it. Steps are whole, so the distance is within one step's travel.
    const int sphere = session::first_kinematic_sphere(world);
    const Vec3 expected =
        session::arrow_drive(Vec3::Zero(), session::Arrow::Right, s.camera.yaw_degrees);
    const Vec3 c0 = world.sphere(sphere).center;
    const double t0 = run.time();
    press_arrow(s, session::Arrow::Right);
    run.advance_to(t0 + 0.1);
    const Vec3 moved = world.sphere(sphere).center - c0;
    const double tolerance = 1.5 * run.step() * session::kDriveSpeed + 1e-9;
    if ((moved - expected * (run.time() - t0)).norm() > tolerance)
      fail("the right arrow moved the sphere by (" + std::to_string(moved.x()) + ", " +
           std::to_string(moved.y()) + ", " + std::to_string(moved.z()) + ") m in " +
           std::to_string(run.time() - t0) + " s");
    stop_sphere(s);
    const Vec3 c1 = world.sphere(sphere).center;
    run.advance_to(run.time() + 0.1);
    if ((world.sphere(sphere).center - c1).norm() > 1e-12) fail("S did not stop the sphere");
    char buf[128];
    std::snprintf(buf, sizeof buf, ", right arrow moved the sphere %.3f m, S stopped it",
                  moved.norm());
    arrows = buf;
  }
  std::printf("smoke: scene %-35s keys 1-4 toggled the corner pins%s\n", s.edited.name.c_str(),
              arrows.c_str());
}

}  // namespace jelly::app
