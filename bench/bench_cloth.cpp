// Speed of the A2 reference on the course's cloth scenes (Google Benchmark; issue 20 "Speed").
// Results: docs/performance.md.
//   BM_Cloth2022/<integrator>  cloth-2022 at h = 1e-4, one core, over its first 2 s (the spheres
//                              land at ≈ 0.32 s; the run is rewound to t = 0 every 2 s)
//   BM_Cloth2024/<integrator>  cloth-2024 likewise over its 3 s schedule
// Counters: real_time_ratio (simulated seconds per second of wall time; ≥ 3 for RK4 on
// cloth-2022 is the target), steps/s and ns_per_spring_eval.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "jelly/a2/task_table.hpp"
#include "jelly/cloth_physics.hpp"
#include "jelly/simulator.hpp"

namespace {

using namespace jelly;

// The scenes' exact settings (scenes/cloth-2022.toml, cloth-2024.toml), built in code.
std::unique_ptr<World> cloth_scene(int year) {
  auto world = std::make_unique<World>(a2::task_table());
  ClothSpec spec;
  spec.center = Vec3(0.0, year == 2022 ? 0.0 : 1.0, 0.0);
  spec.air_drag = 3.4e-4;
  cloth_physics(*world).add_cloth(spec);
  const double ks = year == 2022 ? 25000.0 : 20000.0;
  for (SpringType t : {SpringType::Structural, SpringType::Shear, SpringType::Bending})
    cloth_physics(*world).build_cloth_springs(0, t, ks, 750.0);
  world->set_gravity(Vec3(0.0, -9.8, 0.0));
  ClothCollisionSettings c;
  if (year == 2022) {
    for (double x : {-0.75, 0.75})
      for (double z : {-0.75, 0.75}) {
        SphereSpec s;
        s.center = Vec3(x, 1.0, z);
        s.radius = 0.5;
        cloth_physics(*world).add_sphere(s);
      }
  } else {
    SphereSpec s;
    s.kinematic = true;
    s.radius = 1.0;
    s.schedule = {{0.0, Vec3::Zero()},
                  {0.5, Vec3(2.0, 0.0, 0.0)},
                  {1.0, Vec3(-2.0, 0.0, 0.0)},
                  {1.5, Vec3::Zero()}};
    cloth_physics(*world).add_sphere(s);
  }
  cloth_physics(*world).set_cloth_collisions(c);
  return world;
}

void run_scene(benchmark::State& state, int year, double window) {
  const auto kind = static_cast<IntegratorKind>(state.range(0));
  state.SetLabel("cloth-" + std::to_string(year) + " " + std::string(to_string(kind)));
  const double h = 1e-4;
  const long window_steps = std::lround(window / h);
  std::unique_ptr<Simulator> sim;
  long since = window_steps;
  for (auto _ : state) {
    if (since == window_steps) {  // (re)start the scene at t = 0, outside the timing
      state.PauseTiming();
      Simulator::Options o(kind, h);
      o.detect_instability = false;  // the step itself (the detector costs one energy sum / 10)
      sim = std::make_unique<Simulator>(cloth_scene(year), o);
      since = 0;
      state.ResumeTiming();
    }
    if (sim->step() != StepResult::Ok) {
      state.SkipWithError("unstable");
      break;
    }
    ++since;
  }
  const auto steps = static_cast<double>(state.iterations());
  const double springs = static_cast<double>(sim->world().spring_count());
  state.counters["real_time_ratio"] = benchmark::Counter(steps * h, benchmark::Counter::kIsRate);
  state.counters["steps/s"] = benchmark::Counter(steps, benchmark::Counter::kIsRate);
  state.counters["ns_per_spring_eval"] =
      benchmark::Counter(springs * steps * evaluations_per_step(kind) * 1e-9,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_Cloth2022(benchmark::State& state) { run_scene(state, 2022, 2.0); }
void BM_Cloth2024(benchmark::State& state) { run_scene(state, 2024, 3.0); }

void course_integrators(benchmark::internal::Benchmark* b) {
  for (IntegratorKind k : {IntegratorKind::ExplicitEuler, IntegratorKind::ImplicitEuler,
                           IntegratorKind::Midpoint, IntegratorKind::RK4})
    b->Arg(static_cast<long>(k));
}

}  // namespace

BENCHMARK(BM_Cloth2022)->Apply(course_integrators)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Cloth2024)->Apply(course_integrators)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
