// Inverse kinematics' costs (issue 32, A4; Google Benchmark). Results: docs/performance.md
// ("A4: inverse kinematics"). Every solve runs A4's reference (solutions/a4/, linked from A4's
// reference task library, never a stub) through IkOps built as tests/kinematics/a4_ik_ops.hpp
// builds them, on the course's hw3-ik (data/mocap/IK.amc frame 0, scale 0.2, lowerback →
// rfingers, the contract's target); each is checked before it is timed (73 updates, 105 with
// limits, 1000 and restored when unreachable), or the benchmark stops with an error.
//   BM_Hw3Ik/<impl>             the hw3-ik solve from IK.amc frame 0, µs. impl: reference, plain
//                               (the same iteration written plainly: one forward kinematics per
//                               update with Eigen's AngleAxisd, glibc's sines, and Eigen's
//                               JacobiSVD::solve)
//   BM_Hw3IkLimits/reference    the same with limits (105 updates), µs
//   BM_Unreachable/<impl>       a target 40 units above the head: 1000 updates, restored, ms
//   BM_WarmSolve/<move>         the viewer's frame: from the solved hw3-ik posture, a solve to the
//                               target moved by <move>/1000 scene units (16 directions in turn),
//                               µs
//   BM_ViewerDrag/<step>        the viewer's drag: the player of scenes/hw3-ik.toml with A4's
//                               reference task table (jelly run's path: solve_ik through
//                               make_ik_ops), the target moved by <step>/1000 units along a circle
//                               of radius 0.3 around the course's ball each solve, N solves in a
//                               row, each warm-started from the posture the one before left
//                               (SkeletonPlayer::set_ik_target, then ik_update), µs per solve
//   BM_Part<...>                one update's parts at hw3-ik's first posture, ns: forward
//                               kinematics (31 bones), the Jacobian (from frames), the
//                               least-squares solve (JacobiSVD of the 3 × 27 J), the clamp
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>
#include <string>
#include <vector>

#include "jelly/a4/chain.hpp"
#include "jelly/a4/ik.hpp"
#include "jelly/a4/jacobian.hpp"
#include "jelly/a4/kinematics.hpp"
#include "jelly/a4/least_squares.hpp"
#include "jelly/a4/task_table.hpp"
#include "jelly/scene.hpp"
#include "jelly/skeleton/skeleton_files.hpp"
#include "jelly/skeleton_player.hpp"

namespace {

using namespace jelly;
using skeleton::BoneFrames;
using skeleton::IkOps;
using skeleton::IkResult;
using skeleton::IkSettings;
using skeleton::Matrix3X;
using skeleton::Posture;
using skeleton::Skeleton;
using skeleton::VectorX;

constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

// The course's hw3-ik (contract §7, §8), read once.
struct CourseIk {
  Skeleton skeleton;
  Posture posture;
  std::vector<int> chain;
  Vec3 target = Vec3(-0.0692501, 3.85358, -1.63441);
  bool ok = false;
};

const CourseIk& course_ik() {
  static const CourseIk course = [] {
    CourseIk c;
    const skeleton::SkeletonResult s =
        skeleton::read_asf(JELLY_SOURCE_DIR "/data/mocap/skeleton.asf", 0.2);
    if (!s) return c;
    c.skeleton = *s.skeleton;
    const skeleton::MotionResult m =
        skeleton::read_amc(JELLY_SOURCE_DIR "/data/mocap/IK.amc", c.skeleton);
    const auto start = c.skeleton.find("lowerback"), end = c.skeleton.find("rfingers");
    if (!m || !start || !end) return c;
    c.posture = m.motion->frames.at(0);
    c.chain = a4::ik_chain(c.skeleton, *start, *end);
    c.ok = true;
    return c;
  }();
  return course;
}

// IkOps from A4's reference, as tests/kinematics/a4_ik_ops.hpp makes them.
IkOps reference_ops(const Skeleton& sk, const std::vector<int>& chain, const Vec3& target,
                    const IkSettings& settings) {
  IkOps ops;
  const Skeleton* s = &sk;
  const int end = chain.front();
  ops.end_effector = [s, end](const Posture& p) {
    BoneFrames f;
    a4::forward_kinematics(*s, p, f);
    return Vec3(f.end[end]);
  };
  ops.jacobian = [s, chain](const Posture& p, Matrix3X& J) {
    BoneFrames f;
    a4::forward_kinematics(*s, p, f);
    a4::ik_jacobian(*s, f, chain, J);
  };
  ops.solve = [](const Matrix3X& J, const Vec3& e, VectorX& x) { a4::least_squares(J, e, x); };
  ops.clamp = [s, chain](Posture& p) { a4::clamp_to_limits(*s, chain, p); };
  ops.iterate = [s, chain, target, settings, inner = ops](Posture& p) {
    return a4::ik_iterate(*s, chain, target, settings, inner, p);
  };
  return ops;
}

IkResult reference_solve(const Vec3& target, const IkSettings& settings, Posture& p) {
  const CourseIk& c = course_ik();
  return a4::ik_solve(settings, reference_ops(c.skeleton, c.chain, target, settings), p);
}

// ---- the plain solve -------------------------------------------------------------------------

skeleton::Mat3 plain_euler_matrix(const Vec3& degrees) {
  const Vec3 a = degrees * kRadiansPerDegree;
  return (Eigen::AngleAxisd(a.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(a.y(), Vec3::UnitY()) *
          Eigen::AngleAxisd(a.x(), Vec3::UnitX()))
      .toRotationMatrix();
}

void plain_place(const Skeleton& sk, const Posture& p, int i, BoneFrames& out) {
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

// Contract §6.4 written plainly: one forward kinematics per update (the course's code), the
// Jacobian's columns, Eigen's JacobiSVD::solve (its own threshold), limits off, restore on.
IkResult plain_solve(const Vec3& target, const IkSettings& settings, Posture& posture) {
  const CourseIk& c = course_ik();
  const Skeleton& sk = c.skeleton;
  const Posture input = posture;
  BoneFrames f;
  f.rotation.resize(sk.bones.size());
  f.start.resize(sk.bones.size());
  f.end.resize(sk.bones.size());
  Eigen::MatrixXd J(3, 3 * static_cast<Eigen::Index>(c.chain.size()));
  IkResult r;
  for (r.updates = 0;; ++r.updates) {
    plain_place(sk, posture, 0, f);
    const Vec3 e = target - f.end[c.chain.front()];
    r.error = e.norm();
    if (r.error < settings.epsilon || r.updates >= settings.max_iterations) break;
    J.setZero();
    for (std::size_t b = 0; b < c.chain.size(); ++b) {
      const int i = c.chain[b];
      for (int k = 0; k < 3; ++k)
        if (sk.bones[i].parent < 0 || sk.bones[i].has_rotation(k))
          J.col(3 * b + k) = f.rotation[i].col(k).cross(f.end[c.chain.front()] - f.start[i]);
    }
    const Eigen::VectorXd x =
        Eigen::JacobiSVD<Eigen::MatrixXd>(J, Eigen::ComputeThinU | Eigen::ComputeThinV).solve(e);
    for (std::size_t b = 0; b < c.chain.size(); ++b)
      for (int k = 0; k < 3; ++k)
        if (sk.bones[c.chain[b]].parent < 0 || sk.bones[c.chain[b]].has_rotation(k))
          posture.angles[c.chain[b]][k] += settings.step * x(3 * b + k) / kRadiansPerDegree;
  }
  r.stable = r.error < settings.epsilon;
  if (!r.stable && settings.restore) posture = input;
  return r;
}

// ---- the solves ------------------------------------------------------------------------------

using Solve = IkResult (*)(const Vec3&, const IkSettings&, Posture&);

// Solves from IK.amc frame 0 each iteration; skipped unless the first gives `updates` and
// `stable` (and, when unstable, the input posture back).
void solve(benchmark::State& state, Solve f, const Vec3& target, const IkSettings& settings,
           int updates, bool stable) {
  const CourseIk& c = course_ik();
  if (!c.ok) {
    state.SkipWithError("cannot read data/mocap/skeleton.asf or IK.amc");
    return;
  }
  Posture p = c.posture;
  const IkResult first = f(target, settings, p);
  if (first.updates != updates || first.stable != stable ||
      (!stable && p.angles != c.posture.angles)) {
    state.SkipWithError(("the solve made " + std::to_string(first.updates) + " updates, not " +
                         std::to_string(updates))
                            .c_str());
    return;
  }
  for (auto _ : state) {
    p = c.posture;
    benchmark::DoNotOptimize(f(target, settings, p));
    benchmark::ClobberMemory();
  }
  state.counters["updates"] = updates;
}

Vec3 unreachable_target() {
  const CourseIk& c = course_ik();
  BoneFrames f;
  a4::forward_kinematics(c.skeleton, c.posture, f);
  return f.end[0] + Vec3(0.0, 40.0, 0.0);  // far above the head, as the reference's test
}

IkSettings with_limits() {
  IkSettings s;
  s.limits = true;
  return s;
}

void BM_Hw3Ik_reference(benchmark::State& s) {
  solve(s, reference_solve, course_ik().target, IkSettings{}, 73, true);
}
void BM_Hw3Ik_plain(benchmark::State& s) {
  solve(s, plain_solve, course_ik().target, IkSettings{}, 73, true);
}
void BM_Hw3IkLimits_reference(benchmark::State& s) {
  solve(s, reference_solve, course_ik().target, with_limits(), 105, true);
}
void BM_Unreachable_reference(benchmark::State& s) {
  solve(s, reference_solve, unreachable_target(), IkSettings{}, 1000, false);
}
void BM_Unreachable_plain(benchmark::State& s) {
  solve(s, plain_solve, unreachable_target(), IkSettings{}, 1000, false);
}
BENCHMARK(BM_Hw3Ik_reference)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Hw3Ik_plain)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Hw3IkLimits_reference)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Unreachable_reference)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Unreachable_plain)->Unit(benchmark::kMillisecond);

// ---- the viewer's frame: a warm-started solve after a small move -------------------------------

// From the posture the hw3-ik solve leaves, the target moved by range(0)/1000 units in one of 16
// directions (in turn); the posture is put back before each solve.
void BM_WarmSolve(benchmark::State& state) {
  const CourseIk& c = course_ik();
  if (!c.ok) {
    state.SkipWithError("cannot read data/mocap/skeleton.asf or IK.amc");
    return;
  }
  Posture solved = c.posture;
  if (!reference_solve(c.target, IkSettings{}, solved).stable) {
    state.SkipWithError("hw3-ik did not converge");
    return;
  }
  const double move = static_cast<double>(state.range(0)) / 1000.0;
  std::vector<Vec3> targets;
  for (int k = 0; k < 16; ++k) {
    const double a = 2.0 * 3.14159265358979323846 * k / 16.0;
    targets.push_back(c.target + move * Vec3(std::cos(a), std::sin(a), 0.5 * std::cos(3.0 * a)));
  }
  long updates = 0, unstable = 0, solves = 0;
  Posture p;
  std::size_t i = 0;
  for (auto _ : state) {
    p = solved;
    const IkResult r = reference_solve(targets[i++ & 15], IkSettings{}, p);
    updates += r.updates;
    unstable += r.stable ? 0 : 1;
    ++solves;
    benchmark::ClobberMemory();
  }
  state.counters["updates"] = static_cast<double>(updates) / static_cast<double>(solves);
  state.counters["unstable"] = static_cast<double>(unstable);
}
BENCHMARK(BM_WarmSolve)->Arg(5)->Arg(20)->Arg(100)->Unit(benchmark::kMicrosecond);

// ---- the viewer's drag: a warm-started solve each frame, through the player ---------------------

// The target moves range(0)/1000 units a solve along a circle of radius 0.3 units around the ball
// (in the x-y plane), and never comes back to where a solve started: each solve is warm-started
// from the posture the one before left, as while the mouse drags the ball.
void BM_ViewerDrag(benchmark::State& state) {
  const SceneResult scene = load_scene(std::string(JELLY_SOURCE_DIR) + "/scenes/hw3-ik.toml");
  if (!scene) {
    state.SkipWithError("cannot read scenes/hw3-ik.toml");
    return;
  }
  const TaskTable table = a4::task_table();
  SkeletonPlayer player(*scene.scene, skeleton_tasks(table));
  if (!player.problem().empty() || player.ik_record(0).result.updates != 73) {
    state.SkipWithError(("the scene's solve: " + player.problem()).c_str());
    return;
  }
  const double radius = 0.3, angle_step = static_cast<double>(state.range(0)) / 1000.0 / radius;
  const Vec3 centre = player.ik_target(0) - Vec3(radius, 0.0, 0.0);
  long updates = 0, unstable = 0, solves = 0;
  for (auto _ : state) {
    const double a = angle_step * static_cast<double>(++solves);
    player.set_ik_target(0, centre + radius * Vec3(std::cos(a), std::sin(a), 0.0));
    player.ik_update();
    const IkSolveRecord& r = player.ik_record(0);
    updates += r.result.updates;
    unstable += r.solved && r.result.stable ? 0 : 1;
  }
  state.counters["updates"] = static_cast<double>(updates) / static_cast<double>(solves);
  state.counters["unstable"] = static_cast<double>(unstable);
}
BENCHMARK(BM_ViewerDrag)->Arg(5)->Arg(20)->Unit(benchmark::kMicrosecond);

// ---- one update's parts ----------------------------------------------------------------------

void BM_PartForwardKinematics(benchmark::State& state) {
  const CourseIk& c = course_ik();
  BoneFrames f;
  for (auto _ : state) {
    a4::forward_kinematics(c.skeleton, c.posture, f);
    benchmark::DoNotOptimize(f.end.data());
    benchmark::ClobberMemory();
  }
}
void BM_PartJacobian(benchmark::State& state) {
  const CourseIk& c = course_ik();
  BoneFrames f;
  a4::forward_kinematics(c.skeleton, c.posture, f);
  Matrix3X J;
  for (auto _ : state) {
    a4::ik_jacobian(c.skeleton, f, c.chain, J);
    benchmark::DoNotOptimize(J.data());
    benchmark::ClobberMemory();
  }
}
void BM_PartLeastSquares(benchmark::State& state) {
  const CourseIk& c = course_ik();
  BoneFrames f;
  a4::forward_kinematics(c.skeleton, c.posture, f);
  Matrix3X J;
  a4::ik_jacobian(c.skeleton, f, c.chain, J);
  const Vec3 e = c.target - f.end[c.chain.front()];
  VectorX x;
  for (auto _ : state) {
    a4::least_squares(J, e, x);
    benchmark::DoNotOptimize(x.data());
    benchmark::ClobberMemory();
  }
}
void BM_PartClamp(benchmark::State& state) {
  const CourseIk& c = course_ik();
  Posture p = c.posture;
  for (auto _ : state) {
    a4::clamp_to_limits(c.skeleton, c.chain, p);
    benchmark::DoNotOptimize(p.angles.data());
    benchmark::ClobberMemory();
  }
}
// The posture copy each solve makes for its restore.
void BM_PartPostureCopy(benchmark::State& state) {
  const CourseIk& c = course_ik();
  for (auto _ : state) {
    Posture p = c.posture;
    benchmark::DoNotOptimize(p.angles.data());
  }
}
BENCHMARK(BM_PartForwardKinematics);
BENCHMARK(BM_PartJacobian);
BENCHMARK(BM_PartLeastSquares);
BENCHMARK(BM_PartClamp);
BENCHMARK(BM_PartPostureCopy);

}  // namespace

BENCHMARK_MAIN();
