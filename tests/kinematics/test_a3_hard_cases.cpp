// The kinematics contract §10, "hard cases stay numerically stable", on A3's reference
// (solutions/a3/) and the framework's rotations: gimbal lock (ry = ±90° and within 1e-3° of it,
// contract §11.9's bounds), slerp of antipodal and of nearly equal quaternions inside a warp, a
// keyframe warp with K_in < K_out, and a motion of two frames. docs/skeleton-studies.md lists them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>

#include "course_mocap.hpp"
#include "jelly/a3/kinematics.hpp"
#include "jelly/a3/time_warp.hpp"
#include "jelly/skeleton/rotation.hpp"
#include "jelly/skeleton/skeleton_files.hpp"

namespace jelly {
namespace {

using skeleton::euler_to_quaternion;
using skeleton::Motion;
using skeleton::Posture;
using skeleton::Quaternion;
using skeleton::quaternion_to_euler;
using skeleton::same_rotation;
using skeleton::Skeleton;

using testing::course_motion;
using testing::course_skeleton;
using testing::kMocap;

bool finite(const Posture& p) {
  for (const Vec3& a : p.angles)
    if (!a.allFinite()) return false;
  return p.root_translation.allFinite();
}

/// The motion of two frames: `motion`'s frames `a` and `b`.
Motion two_frames(const Motion& motion, int a, int b) {
  Motion m = motion;
  m.frames = {motion.frames[a], motion.frames[b]};
  return m;
}

Posture warped(const Skeleton& s, const Motion& m, double time) {
  Posture p = Posture::zero(s.bones.size());
  a3::warped_posture(s, m, time, p);
  return p;
}

// ----- gimbal lock (contract §11.9) -----

// Within 1e-3° of ry = ±90°, for any rx and rz, the round trip through quaternion_to_euler gives
// the same rotation to 2e-6 (every quaternion coefficient), ry within [−90°, 90°], finite angles;
// at ry = ±90° exactly it is exact to 1e-12.
TEST(A3HardCases, GimbalLockRoundTripsWithinTheContractsBound) {
  std::mt19937_64 random(38);
  std::uniform_real_distribution<double> angle(-180.0, 180.0);
  int checked = 0;
  for (double sign : {1.0, -1.0})
    for (double off : {0.0, 1e-12, 1e-9, 1e-6, 1e-5, 8e-5, 8.2e-5, 1e-4, 5e-4, 1e-3})
      for (int k = 0; k < 50; ++k) {
        const Vec3 a(angle(random), sign * (90.0 - off), angle(random));
        const Quaternion q = euler_to_quaternion(a);
        const Vec3 e = quaternion_to_euler(q);
        ASSERT_TRUE(e.allFinite()) << a.transpose();
        ASSERT_LE(std::fabs(e.y()), 90.0) << a.transpose();
        ASSERT_TRUE(same_rotation(euler_to_quaternion(e), q, off == 0.0 ? 1e-12 : 2e-6))
            << "angles " << a.transpose() << " came back as " << e.transpose();
        ++checked;
      }
  EXPECT_EQ(checked, 1000);
}

// Forward kinematics of a posture with every bone at ry = ±90° is finite, and the bones end where
// the same posture's round-tripped angles put them (to 2e-6 of a rotation times the bone lengths).
TEST(A3HardCases, ForwardKinematicsAtGimbalLockIsFiniteAndRoundTrips) {
  const Skeleton s = course_skeleton();
  Posture locked = Posture::zero(s.bones.size());
  for (std::size_t b = 0; b < s.bones.size(); ++b)
    locked.angles[b] = Vec3(10.0 + b, (b % 2 ? 90.0 : -90.0), -30.0 + b);
  Posture round = locked;
  for (Vec3& a : round.angles) a = quaternion_to_euler(euler_to_quaternion(a));
  skeleton::BoneFrames f, g;
  a3::forward_kinematics(s, locked, f);
  a3::forward_kinematics(s, round, g);
  for (std::size_t b = 0; b < s.bones.size(); ++b) {
    ASSERT_TRUE(f.end[b].allFinite()) << s.bones[b].name;
    EXPECT_LT((f.end[b] - g.end[b]).norm(), 1e-5) << s.bones[b].name;
  }
}

// A warp through gimbal lock: a bone going from ry = 80° to ry = 100° (past the pole) is
// interpolated through the pole with finite angles, and its halfway rotation is the slerp.
TEST(A3HardCases, AWarpThroughGimbalLockIsFiniteAndTheSlerp) {
  const Skeleton s = course_skeleton();
  Motion m = two_frames(course_motion(s, "walk.amc"), 0, 1);
  const int humerus = *s.find("rhumerus");
  m.frames[0].angles[humerus] = Vec3(20.0, 80.0, -10.0);
  m.frames[1].angles[humerus] = Vec3(20.0, 100.0, -10.0);
  for (double t : {0.25, 0.5, 0.75}) {
    const Posture p = warped(s, m, t);
    ASSERT_TRUE(finite(p)) << t;
    const Quaternion want = skeleton::slerp(euler_to_quaternion(m.frames[0].angles[humerus]),
                                            euler_to_quaternion(m.frames[1].angles[humerus]), t);
    EXPECT_TRUE(same_rotation(euler_to_quaternion(p.angles[humerus]), want, 2e-6))
        << t << ": " << p.angles[humerus].transpose();
  }
}

// ----- slerp's two edges, inside a warp -----

// Two Euler triples of one rotation whose quaternions are antipodal: the warp stays on that
// rotation (the short path) instead of spinning a full turn, with unit quaternions.
TEST(A3HardCases, AWarpBetweenAntipodalQuaternionsStaysPut) {
  const Skeleton s = course_skeleton();
  Motion m = two_frames(course_motion(s, "walk.amc"), 0, 1);
  const int femur = *s.find("lfemur");
  const Vec3 a(30.0, 20.0, 10.0), b(30.0 + 360.0, 20.0, 10.0);  // the same rotation, q_b = −q_a
  ASSERT_LT(euler_to_quaternion(a).dot(euler_to_quaternion(b)), -0.999999);
  m.frames[0].angles[femur] = a;
  m.frames[1].angles[femur] = b;
  for (double t : {0.1, 0.5, 0.9}) {
    const Posture p = warped(s, m, t);
    ASSERT_TRUE(finite(p)) << t;
    EXPECT_TRUE(same_rotation(euler_to_quaternion(p.angles[femur]), euler_to_quaternion(a), 1e-12))
        << t << ": " << p.angles[femur].transpose();
  }
}

// Nearly equal rotations (down to equal): slerp's nlerp band, no 0/0, the rotation in between.
TEST(A3HardCases, AWarpBetweenNearlyEqualRotationsIsFiniteAndUnit) {
  const Skeleton s = course_skeleton();
  Motion m = two_frames(course_motion(s, "walk.amc"), 0, 1);
  const int femur = *s.find("lfemur");
  for (double tiny : {1e-6, 1e-9, 1e-12, 1e-15, 0.0}) {
    m.frames[0].angles[femur] = Vec3(30.0, 20.0, 10.0);
    m.frames[1].angles[femur] = Vec3(30.0, 20.0, 10.0 + tiny);
    const Quaternion l = euler_to_quaternion(m.frames[0].angles[femur]);
    const Quaternion r = euler_to_quaternion(m.frames[1].angles[femur]);
    const Quaternion q = skeleton::slerp(l, r, 0.5);
    ASSERT_TRUE(q.coeffs().allFinite()) << tiny;
    EXPECT_NEAR(q.norm(), 1.0, 1e-15) << tiny;
    const Posture p = warped(s, m, 0.5);
    ASSERT_TRUE(finite(p)) << tiny;
    const Quaternion halfway = euler_to_quaternion(Vec3(30.0, 20.0, 10.0 + tiny / 2.0));
    EXPECT_TRUE(same_rotation(euler_to_quaternion(p.angles[femur]), halfway, 1e-12)) << tiny;
  }
}

// ----- warps at their edges -----

// K_in < K_out (input 100 lands on output 300 of 450: a slow start, a fast end): s is monotone,
// hits 0, K_in and N − 1 exactly, stays in [0, N − 1], and every warped posture is finite.
TEST(A3HardCases, AKeyframeWarpWithKinBelowKoutIsMonotoneExactAndFinite) {
  const Skeleton s = course_skeleton();
  const Motion punch = course_motion(s, "punch_kick.amc");
  skeleton::TimeWarp w;
  w.input_frames = 450;
  w.output_frames = 450;
  w.keyframe_in = 100;
  w.keyframe_out = 300;
  double before = -1.0;
  for (int i = 0; i < w.output_frames; ++i) {
    const double t = a3::time_map(i, w);
    ASSERT_GE(t, before) << i;
    ASSERT_LE(t, 449.0) << i;
    before = t;
    ASSERT_TRUE(finite(warped(s, punch, t))) << i;
  }
  EXPECT_EQ(a3::time_map(0, w), 0.0);
  EXPECT_EQ(a3::time_map(300, w), 100.0);
  EXPECT_EQ(a3::time_map(449, w), 449.0);
  EXPECT_LT(a3::time_map(150, w), 150.0) << "slower than the input before the keyframe";
}

// A motion of two frames (N = 2, the least §5 allows) retimed to 2 and to 9 frames: s never
// reaches past frame 1, the ends are the input frames, the middle frames the slerp of the two.
TEST(A3HardCases, AMotionOfTwoFramesWarpsBetweenItsFrames) {
  const Skeleton s = course_skeleton();
  const Motion m = two_frames(course_motion(s, "walk.amc"), 0, 60);
  for (int frames : {2, 9}) {
    skeleton::TimeWarp w;
    w.input_frames = 2;
    w.output_frames = frames;
    EXPECT_EQ(a3::time_map(0, w), 0.0);
    EXPECT_EQ(a3::time_map(frames - 1, w), 1.0);
    for (int i = 0; i < frames; ++i) {
      const double t = a3::time_map(i, w);
      ASSERT_TRUE(t >= 0.0 && t <= 1.0) << frames << ": " << i << " -> " << t;
      const Posture p = warped(s, m, t);
      ASSERT_TRUE(finite(p)) << i;
      for (std::size_t b = 0; b < s.bones.size(); ++b) {
        if (s.bones[b].channels.empty()) continue;
        const Quaternion want = skeleton::slerp(euler_to_quaternion(m.frames[0].angles[b]),
                                                euler_to_quaternion(m.frames[1].angles[b]), t);
        ASSERT_TRUE(same_rotation(euler_to_quaternion(p.angles[b]), want, 1e-9))
            << s.bones[b].name << " at s = " << t;
      }
    }
  }
}

}  // namespace
}  // namespace jelly
