#include "hard_run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "jelly/a1/task_table.hpp"
#include "jelly/cube_scene.hpp"
#include "jelly/particles_scene.hpp"
#include "jelly/terrain_geometry.hpp"

namespace jelly::hard {

Expect predict(const StabilityEstimate& e, IntegratorKind kind, double h) {
  if (h <= e.recommended_step(kind)) return Expect::Stable;
  if (h > 1.1 * e.critical_step(kind)) return Expect::Unstable;
  return Expect::Either;
}

const char* to_string(Expect e) {
  switch (e) {
    case Expect::Stable: return "stable";
    case Expect::Unstable: return "unstable";
    case Expect::Either: return "near the limit";
  }
  return "?";
}

std::string Outcome::summary() const {
  char buf[512];
  if (stopped)
    std::snprintf(buf, sizeof buf, "stopped at step %ld (t = %.4g s): %s", report->step,
                  report->time, report->reason.c_str());
  else
    std::snprintf(buf, sizeof buf,
                  "stable for %.3g s (%ld steps): E_max - E0 = %.3g J (allowed %.3g J), deepest "
                  "%.3g m (bound %.3g m), v_peak %.3g m/s",
                  time, steps, energy_max - energy_start, energy_margin, max_depth, depth_bound,
                  v_peak);
  return buf;
}

SceneSpec load_hard_scene(const std::string& name) {
  const auto path = std::filesystem::path(JELLY_SOURCE_DIR) / "scenes" / "hard" / (name + ".toml");
  const SceneResult r = load_scene(path);
  EXPECT_TRUE(r) << (r.error ? r.error->text() : std::string());
  return r ? *r.scene : SceneSpec{};
}

StabilityEstimate estimate_for(const SceneSpec& scene) {
  // Power iteration on the n = 30 cube takes seconds: estimate each scene once per test binary.
  // The key is the scene as written back to TOML, so an edited scene gets its own estimate.
  static std::map<std::string, StabilityEstimate> cache;
  const std::string key = to_toml(scene);
  if (const auto it = cache.find(key); it != cache.end()) return it->second;
  auto world = build_world(scene, a1::task_table());
  return cache[key] = estimate_stability(*world, world->state());
}

Outcome run_case(const SceneSpec& scene, IntegratorKind kind, double h, double horizon) {
  Simulator sim(build_world(scene, a1::task_table()), Simulator::Options(kind, h));
  Outcome o;
  o.energy_start = o.energy_max = sim.energy().total();
  const auto& cfg = sim.options().monitor;
  o.energy_margin = cfg.relative_margin * std::abs(o.energy_start) + cfg.absolute_floor;
  const long total = std::lround(horizon / h);
  const std::vector<Terrain>& terrains = sim.world().terrains();
  while (sim.steps() < total) {
    if (sim.step() == StepResult::Unstable) {
      o.stopped = true;
      o.report = *sim.instability();
      break;
    }
    const State& s = sim.state();
    if (!(s.x.allFinite() && s.v.allFinite())) {
      o.finite = false;  // the detector samples every 10 steps; it must catch this by then
      continue;
    }
    o.energy_max = std::max(o.energy_max, sim.energy().total());
    for (Eigen::Index i = 0; i < s.size(); ++i) {
      o.v_peak = std::max(o.v_peak, s.v.col(i).norm());
      for (const Terrain& t : terrains) {
        const Vec3 x = s.x.col(i);
        if (in_extent(t, x)) o.max_depth = std::max(o.max_depth, -signed_distance(t, x));
      }
    }
  }
  o.time = sim.time();
  o.steps = sim.steps();
  double eps = 0.0;
  for (const Terrain& t : terrains) eps = std::max(eps, t.surface().epsilon);
  // The lattice spacing: the cube's, or the shortest explicit spring's rest length.
  double spacing =
      scene.body_kind == kCubeKind ? cube_spec(scene).edge / (cube_spec(scene).n - 1) : 1.0;
  if (scene.body_kind == BodyKind{"particles"})
    for (const Spring& sp : particles_scene(scene).springs)
      spacing = std::min(spacing, sp.rest_length);
  o.depth_bound = eps + 2.0 * h * o.v_peak + spacing;
  return o;
}

}  // namespace jelly::hard
