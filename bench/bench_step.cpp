// Steps per second of the reference engine (Google Benchmark). Results: docs/performance.md.
//   BM_Step/<integrator>/<n>     course 2023 scene, cube in flight (t = 0), one core
//   BM_StepResting/<integrator>  the same after 10 s, resting in the bowl (contact active)
//   BM_StepSprings/<types>       cost of a step following the scene: structural only vs full cube
//   BM_StepThreads/<n>/<threads> explicit Euler with the spring pass on 1 or 2 threads (wall time)
#include <benchmark/benchmark.h>

#include "jelly/a1/task_table.hpp"
#include "jelly/cube_scene.hpp"
#include "jelly/scene.hpp"
#include "jelly/simulator.hpp"

namespace {

using namespace jelly;

SceneSpec course_scene(int n, IntegratorKind kind) {
  SceneSpec s = course_2023_scene();
  s.integrator = kind;
  cube_spec(s).n = n;
  return s;
}

// Steps the simulator; with `rewind`, puts the initial state back every 500 steps (0.5 s of
// flight, before the cube reaches the floor at ≈ 1.4 s) so that the measured state stays the same.
void run_steps(benchmark::State& state, Simulator& sim, bool rewind) {
  const State start = sim.state();
  long since = 0;
  for (auto _ : state) {
    if (sim.step() != StepResult::Ok) {
      state.SkipWithError("unstable");
      break;
    }
    if (rewind && ++since == 500) {
      sim.world().state() = start;
      since = 0;
    }
  }
  state.counters["steps/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["springs"] = static_cast<double>(sim.world().spring_count());
  // Per spring and acceleration evaluation: the rate inverted, in ns.
  state.counters["ns_per_spring_eval"] = benchmark::Counter(
      static_cast<double>(sim.world().spring_count()) * static_cast<double>(state.iterations()) *
          evaluations_per_step(sim.options().integrator) * 1e-9,
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_Step(benchmark::State& state) {
  const auto kind = static_cast<IntegratorKind>(state.range(0));
  const int n = static_cast<int>(state.range(1));
  state.SetLabel(std::string(to_string(kind)) + " n=" + std::to_string(n));
  Simulator::Options o(kind, 0.001);
  o.detect_instability = false;  // measure the step itself; the detector costs ~1/10 of a pass
  Simulator sim(build_world(course_scene(n, kind), a1::task_table()), o);
  run_steps(state, sim, true);
}

void BM_StepResting(benchmark::State& state) {
  const auto kind = static_cast<IntegratorKind>(state.range(0));
  state.SetLabel(std::string(to_string(kind)) + " resting in the bowl");
  Simulator::Options o(IntegratorKind::RK4, 0.001);
  Simulator settle(build_world(course_scene(10, IntegratorKind::RK4), a1::task_table()), o);
  settle.run_until(10.0);
  SceneSpec s = course_scene(10, kind);
  auto world = build_world(s, a1::task_table());
  world->state() = settle.state();
  Simulator::Options o2(kind, 0.001);
  o2.detect_instability = false;
  Simulator sim(std::move(world), o2);
  run_steps(state, sim, false);
}

void BM_StepSprings(benchmark::State& state) {
  const bool full = state.range(0) != 0;
  state.SetLabel(full ? "full cube (12876 springs)" : "structural only (2700 springs)");
  SceneSpec s = course_scene(10, IntegratorKind::ExplicitEuler);
  if (!full) s.shear.enabled = s.bending.enabled = false;
  Simulator::Options o(IntegratorKind::ExplicitEuler, 0.001);
  o.detect_instability = false;
  Simulator sim(build_world(s, a1::task_table()), o);
  run_steps(state, sim, true);
}

// Explicit Euler with the spring pass split among 1 or 2 threads (World::set_force_threads).
void BM_StepThreads(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  state.SetLabel("explicit_euler n=" + std::to_string(n) + " threads=" + std::to_string(threads));
  Simulator::Options o(IntegratorKind::ExplicitEuler, 0.001);
  o.detect_instability = false;
  auto world = build_world(course_scene(n, IntegratorKind::ExplicitEuler), a1::task_table());
  world->set_force_threads(threads);
  Simulator sim(std::move(world), o);
  run_steps(state, sim, true);
}

void integrators_n10(benchmark::internal::Benchmark* b) {
  for (IntegratorKind k : kAllIntegrators) b->Args({static_cast<long>(k), 10});
}
void sizes(benchmark::internal::Benchmark* b) {
  for (int n : {10, 20, 30}) b->Args({static_cast<long>(IntegratorKind::ExplicitEuler), n});
  for (int n : {10, 20, 30}) b->Args({static_cast<long>(IntegratorKind::RK4), n});
}

}  // namespace

BENCHMARK(BM_Step)->Apply(integrators_n10)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Step)->Name("BM_StepSize")->Apply(sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StepResting)->DenseRange(0, 5)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StepSprings)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StepThreads)
    ->ArgsProduct({{10, 30}, {1, 2}})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();
BENCHMARK_MAIN();
