// The skeleton module's costs (issue 31, A3) and the portable functions they rest on (Google
// Benchmark). Results: docs/performance.md ("Skeletons and the portable sines").
//   BM_Sin/<impl>, BM_Cos, BM_SinCos, BM_Atan2, BM_Asin, BM_Acos   one call, ns
//       impl: portable (fast path, falling back to the accurate one), accurate
//       (portable::detail::*_accurate, the only path before), libm (the C library's, for scale)
//   BM_EulerToQuaternion, BM_QuaternionToEuler, BM_Slerp           one call, ns
//   BM_PostureRotations    E(angles) of every bone of one posture of punch_kick.amc, ns
//   BM_ForwardKinematics/<impl>   forward kinematics of the course's 31-bone skeleton, one posture
//       of punch_kick.amc per iteration (all 450 in turn), ns. impl: reference (A3's, from
//       solutions/tasks/kinematics/kinematics.cpp, portable sines), plain (the same tree walk with
//       Eigen's AngleAxisd products: the C library's sin and cos)
//   BM_ReadAmc/<impl>      data/mocap/punch_kick.amc read into a Motion (skeleton read once), ms.
//       impl: reference (skeleton::read_amc: tokens, checks, errors), plain (std::ifstream and
//       operator>>, no checks)
//   BM_Warp/<impl>         the 2022 scene's keyframe warp: punch_kick 450 → 450 frames, K_in 160 →
//       K_out 150, every output posture, ms. impl: reference (A3's time_map and warped_posture),
//       plain (the same time map; Eigen's AngleAxisd, Quaterniond::slerp and eulerAngles)
// Arguments cycle through 1024 values drawn with a fixed seed: angles in degrees in [−180°, 180°]
// converted to radians (what the rotations pass), matrix entries in [−1, 1] for the arcs.
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <vector>

#include <fstream>
#include <string>
#include <unordered_map>

#include "jelly/a3/kinematics.hpp"
#include "jelly/a3/time_warp.hpp"
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

// The course's motion, read once for the benchmarks that need one.
const skeleton::Motion* course_motion() {
  static const skeleton::MotionResult r =
      course_skeleton() != nullptr
          ? skeleton::read_amc(JELLY_SOURCE_DIR "/data/mocap/punch_kick.amc", *course_skeleton())
          : skeleton::MotionResult{};
  return r ? &*r.motion : nullptr;
}

// ---- forward kinematics ----------------------------------------------------------------------

// E(θ) = R_z·R_y·R_x the plain way: Eigen's angle-axis rotations (glibc's sin and cos).
skeleton::Mat3 plain_euler_matrix(const Vec3& degrees) {
  const Vec3 a = degrees * kRadiansPerDegree;
  return (Eigen::AngleAxisd(a.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(a.y(), Vec3::UnitY()) *
          Eigen::AngleAxisd(a.x(), Vec3::UnitX()))
      .toRotationMatrix();
}

// Contract §4 written plainly: recursion from the root, R_i = R_p·C_i·E(θ_i).
void plain_place(const skeleton::Skeleton& sk, const skeleton::Posture& p, int i,
                 skeleton::BoneFrames& out) {
  const skeleton::Bone& bone = sk.bones[i];
  if (bone.parent < 0) {
    out.rotation[i] = plain_euler_matrix(p.angles[i]);
    out.start[i] = out.end[i] = p.root_translation;
  } else {
    out.rotation[i] = out.rotation[bone.parent] * bone.C * plain_euler_matrix(p.angles[i]);
    out.start[i] = out.end[bone.parent];
    out.end[i] = out.start[i] + bone.L * (out.rotation[i] * bone.d);
  }
  for (int child : bone.children) plain_place(sk, p, child, out);
}

void plain_forward_kinematics(const skeleton::Skeleton& sk, const skeleton::Posture& p,
                              skeleton::BoneFrames& out) {
  out.rotation.resize(sk.bones.size());
  out.start.resize(sk.bones.size());
  out.end.resize(sk.bones.size());
  plain_place(sk, p, 0, out);
}

// One posture per iteration, all 450 of punch_kick.amc in turn; `out` is reused (as the skeleton
// kind's playback reuses it). Skipped if the two disagree by more than 1e-9 anywhere.
template <class Fk>
void forward_kinematics(benchmark::State& state, Fk fk) {
  const skeleton::Skeleton* sk = course_skeleton();
  const skeleton::Motion* m = course_motion();
  if (sk == nullptr || m == nullptr) {
    state.SkipWithError("cannot read data/mocap/skeleton.asf or punch_kick.amc");
    return;
  }
  skeleton::BoneFrames out, check;
  fk(*sk, m->frames[100], out);
  a3::forward_kinematics(*sk, m->frames[100], check);
  for (std::size_t b = 0; b < sk->bones.size(); ++b) {
    if ((out.end[b] - check.end[b]).norm() > 1e-9 ||
        !(out.rotation[b] - check.rotation[b]).isZero(1e-9)) {
      state.SkipWithError("the plain forward kinematics differs from the reference");
      return;
    }
  }
  std::size_t i = 0;
  for (auto _ : state) {
    fk(*sk, m->frames[i], out);
    benchmark::DoNotOptimize(out.end.data());
    benchmark::ClobberMemory();
    if (++i == m->frames.size()) i = 0;
  }
  state.counters["bones"] = static_cast<double>(sk->bones.size());
}

void BM_ForwardKinematics_reference(benchmark::State& s) {
  forward_kinematics(s, a3::forward_kinematics);
}
void BM_ForwardKinematics_plain(benchmark::State& s) {
  forward_kinematics(s, plain_forward_kinematics);
}
BENCHMARK(BM_ForwardKinematics_reference);
BENCHMARK(BM_ForwardKinematics_plain);

// ---- reading the AMC file --------------------------------------------------------------------

// A straightforward AMC reader for scale: skip the header, then words; a number starts a frame, a
// bone name is followed by its channels' values. No checks, no line numbers, no errors.
skeleton::Motion plain_read_amc(const char* path, const skeleton::Skeleton& sk) {
  std::unordered_map<std::string, int> index;
  for (std::size_t b = 0; b < sk.bones.size(); ++b) index[sk.bones[b].name] = static_cast<int>(b);
  std::ifstream in(path);
  std::string word;
  while (in.peek() == '#' || in.peek() == ':') std::getline(in, word);
  skeleton::Motion m;
  while (in >> word) {
    if (word[0] >= '0' && word[0] <= '9') {
      m.frames.push_back(skeleton::Posture::zero(sk.bones.size()));
      continue;
    }
    const int b = index.at(word);
    skeleton::Posture& p = m.frames.back();
    for (skeleton::Channel c : sk.bones[b].channels) {
      double v = 0.0;
      in >> v;
      const int k = static_cast<int>(c);
      if (k < 3) {
        p.root_translation[k] = sk.scale * v;
      } else {
        p.angles[b][k - 3] = v;
      }
    }
  }
  return m;
}

template <class Read>
void read_amc(benchmark::State& state, Read read) {
  const skeleton::Skeleton* sk = course_skeleton();
  const skeleton::Motion* reference = course_motion();
  if (sk == nullptr || reference == nullptr) {
    state.SkipWithError("cannot read data/mocap/skeleton.asf or punch_kick.amc");
    return;
  }
  const skeleton::Motion first = read(*sk);
  if (first.frames.size() != reference->frames.size() ||
      first.frames.back().angles != reference->frames.back().angles) {
    state.SkipWithError("this reader's motion differs from skeleton::read_amc's");
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(read(*sk).frames.data());
  state.counters["frames"] = static_cast<double>(first.frames.size());
}

void BM_ReadAmc_reference(benchmark::State& s) {
  read_amc(s, [](const skeleton::Skeleton& sk) {
    skeleton::MotionResult r =
        skeleton::read_amc(JELLY_SOURCE_DIR "/data/mocap/punch_kick.amc", sk);
    return r ? std::move(*r.motion) : skeleton::Motion{};
  });
}
void BM_ReadAmc_plain(benchmark::State& s) {
  read_amc(s, [](const skeleton::Skeleton& sk) {
    return plain_read_amc(JELLY_SOURCE_DIR "/data/mocap/punch_kick.amc", sk);
  });
}
BENCHMARK(BM_ReadAmc_reference)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadAmc_plain)->Unit(benchmark::kMillisecond);

// ---- the keyframe warp -----------------------------------------------------------------------

// The 2022 scene hw2-warp-2022: punch_kick.amc, 450 → 450 frames, input 160 on output 150.
skeleton::TimeWarp warp_2022(const skeleton::Motion& m) {
  skeleton::TimeWarp w;
  w.input_frames = static_cast<int>(m.frames.size());
  w.output_frames = 450;
  w.keyframe_in = 160;
  w.keyframe_out = 150;
  return w;
}

Eigen::Quaterniond plain_quaternion(const Vec3& degrees) {
  const Vec3 a = degrees * kRadiansPerDegree;
  return Eigen::AngleAxisd(a.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(a.y(), Vec3::UnitY()) *
         Eigen::AngleAxisd(a.x(), Vec3::UnitX());
}

// The warped posture the plain way: Eigen's slerp, and eulerAngles(2, 1, 0) = (rz, ry, rx).
void plain_warped_posture(const skeleton::Skeleton& sk, const skeleton::Motion& in, double s,
                          skeleton::Posture& out) {
  const int l = static_cast<int>(s);
  const int r = std::min(l + 1, static_cast<int>(in.frames.size()) - 1);
  const double t = s - l;
  out.angles.assign(sk.bones.size(), Vec3::Zero());
  out.root_translation =
      (1.0 - t) * in.frames[l].root_translation + t * in.frames[r].root_translation;
  for (std::size_t b = 0; b < sk.bones.size(); ++b) {
    if (sk.bones[b].channels.empty()) continue;
    const Eigen::Quaterniond q =
        plain_quaternion(in.frames[l].angles[b]).slerp(t, plain_quaternion(in.frames[r].angles[b]));
    const Vec3 zyx = q.toRotationMatrix().eulerAngles(2, 1, 0) / kRadiansPerDegree;
    out.angles[b] = Vec3(zyx.z(), zyx.y(), zyx.x());
  }
}

// Whether both warps give the same rotations (compared as rotations) at input time s.
bool same_warped_posture(const skeleton::Skeleton& sk, const skeleton::Motion& m, double s) {
  skeleton::Posture plain, reference;
  plain_warped_posture(sk, m, s, plain);
  a3::warped_posture(sk, m, s, reference);
  for (std::size_t b = 0; b < sk.bones.size(); ++b) {
    if (!skeleton::same_rotation(skeleton::euler_to_quaternion(plain.angles[b]),
                                 skeleton::euler_to_quaternion(reference.angles[b]), 1e-9))
      return false;
  }
  return (plain.root_translation - reference.root_translation).norm() <= 1e-12;
}

template <class Warp>
void keyframe_warp(benchmark::State& state, Warp warp) {
  const skeleton::Skeleton* sk = course_skeleton();
  const skeleton::Motion* m = course_motion();
  if (sk == nullptr || m == nullptr) {
    state.SkipWithError("cannot read data/mocap/skeleton.asf or punch_kick.amc");
    return;
  }
  const skeleton::TimeWarp w = warp_2022(*m);
  if (!same_warped_posture(*sk, *m, a3::time_map(200, w))) {
    state.SkipWithError("the plain warp differs from the reference");
    return;
  }
  skeleton::Motion out;
  out.frames.resize(static_cast<std::size_t>(w.output_frames));
  for (auto _ : state) {
    for (int i = 0; i < w.output_frames; ++i) warp(*sk, *m, a3::time_map(i, w), out.frames[i]);
    benchmark::DoNotOptimize(out.frames.data());
    benchmark::ClobberMemory();
  }
  state.counters["frames"] = static_cast<double>(w.output_frames);
}

void BM_Warp_reference(benchmark::State& s) { keyframe_warp(s, a3::warped_posture); }
void BM_Warp_plain(benchmark::State& s) { keyframe_warp(s, plain_warped_posture); }
BENCHMARK(BM_Warp_reference)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Warp_plain)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
