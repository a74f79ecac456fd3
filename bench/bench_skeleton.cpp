// The skeleton module's costs (issue 31, A3) and the portable functions they rest on (Google
// Benchmark). Results: docs/performance.md ("Skeletons and the portable sines").
//   BM_Sin/<impl>, BM_Cos, BM_SinCos, BM_Atan2, BM_Asin, BM_Acos   one call, ns
//       impl: portable (fast path, falling back to the accurate one), accurate
//       (portable::detail::*_accurate, the only path before), libm (the C library's, for scale)
//   BM_EulerToQuaternion, BM_QuaternionToEuler, BM_Slerp           one call, ns
//   BM_PostureRotations    E(angles) of every bone of one posture of punch_kick.amc, ns
//   BM_ReadAmc             read_amc of data/mocap/punch_kick.amc (the skeleton read once), ms
// Arguments cycle through 1024 values drawn with a fixed seed: angles in degrees in [−180°, 180°]
// converted to radians (what the rotations pass), matrix entries in [−1, 1] for the arcs.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "jelly/portable_math.hpp"
#include "jelly/skeleton/rotation.hpp"
#include "jelly/skeleton/skeleton_files.hpp"

namespace {

using namespace jelly;
using skeleton::Quaternion;

constexpr std::size_t kCount = 1024;  // a power of two: index & (kCount − 1)
constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

std::vector<double> uniform(double lo, double hi, double scale) {
  std::mt19937_64 gen(31);
  std::uniform_real_distribution<double> d(lo, hi);
  std::vector<double> v(kCount);
  for (double& x : v) x = d(gen) * scale;
  return v;
}

const std::vector<double>& radians() {
  static const std::vector<double> v = uniform(-180.0, 180.0, kRadiansPerDegree);
  return v;
}

const std::vector<double>& entries() {
  static const std::vector<double> v = uniform(-1.0, 1.0, 1.0);
  return v;
}

template <class F>
void one_argument(benchmark::State& state, const std::vector<double>& args, F f) {
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(f(args[i++ & (kCount - 1)]));
}

template <class F>
void two_arguments(benchmark::State& state, F f) {
  const std::vector<double>& a = entries();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(f(a[i & (kCount - 1)], a[(i + 511) & (kCount - 1)]));
    ++i;
  }
}

// ---- the portable functions, their accurate path and the C library's ------------------------

void BM_Sin_portable(benchmark::State& s) {
  one_argument(s, radians(), [](double x) { return portable::sin(x); });
}
void BM_Sin_accurate(benchmark::State& s) {
  one_argument(s, radians(), portable::detail::sin_accurate);
}
void BM_Sin_libm(benchmark::State& s) {
  one_argument(s, radians(), [](double x) { return std::sin(x); });
}
void BM_Cos_portable(benchmark::State& s) {
  one_argument(s, radians(), [](double x) { return portable::cos(x); });
}
void BM_Cos_accurate(benchmark::State& s) {
  one_argument(s, radians(), portable::detail::cos_accurate);
}
void BM_Cos_libm(benchmark::State& s) {
  one_argument(s, radians(), [](double x) { return std::cos(x); });
}
void BM_SinCos_portable(benchmark::State& s) {
  one_argument(s, radians(), [](double x) {
    double sn = 0.0, cs = 0.0;
    portable::sin_cos(x, sn, cs);
    return sn + cs;
  });
}
void BM_Atan2_portable(benchmark::State& s) {
  two_arguments(s, [](double y, double x) { return portable::atan2(y, x); });
}
void BM_Atan2_accurate(benchmark::State& s) { two_arguments(s, portable::detail::atan2_accurate); }
void BM_Atan2_libm(benchmark::State& s) {
  two_arguments(s, [](double y, double x) { return std::atan2(y, x); });
}
void BM_Asin_portable(benchmark::State& s) {
  one_argument(s, entries(), [](double x) { return portable::asin(x); });
}
void BM_Asin_accurate(benchmark::State& s) {
  one_argument(s, entries(), portable::detail::asin_accurate);
}
void BM_Asin_libm(benchmark::State& s) {
  one_argument(s, entries(), [](double x) { return std::asin(x); });
}
void BM_Acos_portable(benchmark::State& s) {
  one_argument(s, entries(), [](double x) { return portable::acos(x); });
}
void BM_Acos_accurate(benchmark::State& s) {
  one_argument(s, entries(), portable::detail::acos_accurate);
}
void BM_Acos_libm(benchmark::State& s) {
  one_argument(s, entries(), [](double x) { return std::acos(x); });
}

BENCHMARK(BM_Sin_portable);
BENCHMARK(BM_Sin_accurate);
BENCHMARK(BM_Sin_libm);
BENCHMARK(BM_Cos_portable);
BENCHMARK(BM_Cos_accurate);
BENCHMARK(BM_Cos_libm);
BENCHMARK(BM_SinCos_portable);
BENCHMARK(BM_Atan2_portable);
BENCHMARK(BM_Atan2_accurate);
BENCHMARK(BM_Atan2_libm);
BENCHMARK(BM_Asin_portable);
BENCHMARK(BM_Asin_accurate);
BENCHMARK(BM_Asin_libm);
BENCHMARK(BM_Acos_portable);
BENCHMARK(BM_Acos_accurate);
BENCHMARK(BM_Acos_libm);

// ---- the skeleton's rotations --------------------------------------------------------------

std::vector<Vec3> euler_angles() {
  std::mt19937_64 gen(32);
  std::uniform_real_distribution<double> d(-180.0, 180.0);
  std::vector<Vec3> v(kCount);
  for (Vec3& a : v) a = Vec3(d(gen), d(gen), d(gen));
  return v;
}

std::vector<Quaternion> quaternions() {
  std::vector<Quaternion> q;
  for (const Vec3& a : euler_angles()) q.push_back(skeleton::euler_to_quaternion(a));
  return q;
}

void BM_EulerToQuaternion(benchmark::State& state) {
  const std::vector<Vec3> a = euler_angles();
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(skeleton::euler_to_quaternion(a[i++ & (kCount - 1)]));
}
BENCHMARK(BM_EulerToQuaternion);

void BM_QuaternionToEuler(benchmark::State& state) {
  const std::vector<Quaternion> q = quaternions();
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(skeleton::quaternion_to_euler(q[i++ & (kCount - 1)]));
}
BENCHMARK(BM_QuaternionToEuler);

void BM_Slerp(benchmark::State& state) {
  const std::vector<Quaternion> q = quaternions();
  const std::vector<double> t = uniform(0.0, 1.0, 1.0);
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ & (kCount - 1);
    benchmark::DoNotOptimize(skeleton::slerp(q[k], q[(k + 1) & (kCount - 1)], t[k]));
  }
}
BENCHMARK(BM_Slerp);

// ---- the course's files ----------------------------------------------------------------------

const skeleton::Skeleton* course_skeleton() {
  static const skeleton::SkeletonResult r =
      skeleton::read_asf(JELLY_SOURCE_DIR "/data/mocap/skeleton.asf", 1.0);
  return r ? &*r.skeleton : nullptr;
}

// E(angles) of every bone of frame 100 of punch_kick.amc: the rotations a forward-kinematics
// pass needs per posture (without the products along the chains).
void BM_PostureRotations(benchmark::State& state) {
  const skeleton::Skeleton* sk = course_skeleton();
  const skeleton::MotionResult m =
      sk != nullptr ? skeleton::read_amc(JELLY_SOURCE_DIR "/data/mocap/punch_kick.amc", *sk)
                    : skeleton::MotionResult{};
  if (!m) {
    state.SkipWithError("cannot read data/mocap/skeleton.asf or punch_kick.amc");
    return;
  }
  const skeleton::Posture& p = m.motion->frames.at(100);
  for (auto _ : state) {
    for (const Vec3& a : p.angles) benchmark::DoNotOptimize(skeleton::euler_matrix(a));
  }
  state.counters["bones"] = static_cast<double>(p.angles.size());
}
BENCHMARK(BM_PostureRotations);

void BM_ReadAmc(benchmark::State& state) {
  const skeleton::Skeleton* sk = course_skeleton();
  if (sk == nullptr) {
    state.SkipWithError("cannot read data/mocap/skeleton.asf");
    return;
  }
  std::size_t frames = 0;
  for (auto _ : state) {
    const skeleton::MotionResult m =
        skeleton::read_amc(JELLY_SOURCE_DIR "/data/mocap/punch_kick.amc", *sk);
    if (!m) {
      state.SkipWithError("cannot read data/mocap/punch_kick.amc");
      return;
    }
    frames = m.motion->frames.size();
  }
  state.counters["frames"] = static_cast<double>(frames);
}
BENCHMARK(BM_ReadAmc)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
