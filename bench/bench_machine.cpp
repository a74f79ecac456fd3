// The machine's own limits, measured with the project's flags, to say how close the spring pass is
// to them (docs/performance.md): the throughput of sqrt + divide (the spring pass's bound), of
// plain multiply-adds (without FMA: -ffp-contract=off), of streaming memory, and the cost of one
// OpenMP parallel region with a barrier (the threaded pass's fixed price).
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace {

// One sqrt and one division per element, independent across elements (vectorised).
void BM_SqrtDiv(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::vector<double> a(n), out(n);
  for (std::size_t i = 0; i < n; ++i) a[i] = 2.0 + 0.001 * static_cast<double>(i);
  for (auto _ : state) {
    for (std::size_t i = 0; i < n; ++i) out[i] = 1.0 / std::sqrt(a[i]);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_element"] =
      benchmark::Counter(static_cast<double>(n) * static_cast<double>(state.iterations()) * 1e-9,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// 16 independent multiply-add chains per element: arithmetic throughput (flops counted as 2 per
// multiply-add).
void BM_MulAdd(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::vector<double> a(n, 1.0000001), out(n);
  for (auto _ : state) {
    for (std::size_t i = 0; i < n; ++i) {
      double x = a[i];
      for (int k = 0; k < 16; ++k) x = x * 0.999999 + 1e-7;
      out[i] = x;
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.counters["GFlop/s"] = benchmark::Counter(
      32.0 * static_cast<double>(n) * static_cast<double>(state.iterations()) * 1e-9,
      benchmark::Counter::kIsRate);
}

// out = a + b over arrays of the given size: bytes moved per second (24 B per element).
void BM_Stream(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::vector<double> a(n, 1.0), b(n, 2.0), out(n);
  for (auto _ : state) {
    for (std::size_t i = 0; i < n; ++i) out[i] = a[i] + b[i];
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.counters["GB/s"] = benchmark::Counter(
      24.0 * static_cast<double>(n) * static_cast<double>(state.iterations()) * 1e-9,
      benchmark::Counter::kIsRate);
}

}  // namespace

#ifdef _OPENMP
// What the threaded spring pass pays per evaluation for its structure alone: one parallel region
// on two threads with one barrier inside, and no work (wall time per region).
void BM_ParallelRegion(benchmark::State& state) {
  volatile int sink = 0;
  for (auto _ : state) {
#pragma omp parallel num_threads(2)
    {
      if (omp_get_thread_num() == 1) sink = sink + 1;
#pragma omp barrier
    }
  }
  benchmark::DoNotOptimize(sink);
}
BENCHMARK(BM_ParallelRegion)->UseRealTime();
#endif

BENCHMARK(BM_SqrtDiv)->Arg(4096);
BENCHMARK(BM_MulAdd)->Arg(4096);
BENCHMARK(BM_Stream)->Arg(4096)->Arg(1 << 16)->Arg(1 << 22);
BENCHMARK_MAIN();
