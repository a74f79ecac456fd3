// A3's reference (solutions/a3/) against the kinematics contract: §8's numbers on the course's
// files at scale 0.2, the time map's ends and keyframe (§5), the warped posture where s is an
// integer (the input frame itself, compared as a rotation, §3), and the blend's window (§5).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "course_mocap.hpp"
#include "jelly/a3/blend.hpp"
#include "jelly/a3/kinematics.hpp"
#include "jelly/a3/time_warp.hpp"
#include "jelly/portable_math.hpp"
#include "jelly/skeleton/rotation.hpp"
#include "jelly/skeleton/skeleton_files.hpp"

namespace jelly {
namespace {

namespace fs = std::filesystem;
using skeleton::BoneFrames;
using skeleton::Motion;
using skeleton::Posture;
using skeleton::Skeleton;

using testing::course_motion;
using testing::course_skeleton;
using testing::kMocap;

int bone(const Skeleton& s, const std::string& name) {
  const std::optional<int> i = s.find(name);
  EXPECT_TRUE(i.has_value()) << name;
  return i.value_or(0);
}

void expect_near(const Vec3& got, const Vec3& want, double tol, const std::string& what) {
  EXPECT_LE((got - want).cwiseAbs().maxCoeff(), tol)
      << what << ": got (" << got.transpose() << "), want (" << want.transpose() << ")";
}

BoneFrames fk(const Skeleton& s, const Posture& p) {
  BoneFrames f;
  a3::forward_kinematics(s, p, f);
  return f;
}

// ----- T1, T2: §8's numbers -----

TEST(A3Reference, LocalRotationIsTheFrameworksEulerMatrix) {
  for (const Vec3& a : {Vec3(30.0, 20.0, 10.0), Vec3(-170.0, 89.9, 45.0), Vec3(0.0, -90.0, 0.0)}) {
    const skeleton::Mat3 e = a3::local_rotation(a);
    EXPECT_LE((e - skeleton::euler_matrix(a)).cwiseAbs().maxCoeff(), 1e-15) << a.transpose();
    EXPECT_LE((e * e.transpose() - skeleton::Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-15);
  }
  // R_x(90°) turns y into z (right-handed); E applies R_x first, then R_y, then R_z.
  expect_near(a3::local_rotation(Vec3(90.0, 0.0, 0.0)) * Vec3::UnitY(), Vec3::UnitZ(), 1e-15,
              "R_x(90) y");
  expect_near(a3::local_rotation(Vec3(90.0, 0.0, 90.0)) * Vec3::UnitY(), Vec3::UnitZ(), 1e-15,
              "R_z(90) R_x(90) y");
  expect_near(a3::local_rotation(Vec3(0.0, 90.0, 90.0)) * Vec3::UnitX(), -Vec3::UnitZ(), 1e-15,
              "R_z(90) R_y(90) x");
}

TEST(A3Reference, ForwardKinematicsGivesTheContractsNumbersOnIkAmcFrame0) {
  const Skeleton s = course_skeleton();
  const BoneFrames f = fk(s, course_motion(s, "IK.amc").frames[0]);
  ASSERT_EQ(f.end.size(), s.bones.size());
  expect_near(f.start[0], Vec3(0.11819, 3.45750, -3.21486), 1e-5, "root start");
  expect_near(f.end[bone(s, "lowerback")], Vec3(0.13451, 3.87846, -3.14020), 1e-5, "lowerback");
  expect_near(f.end[bone(s, "head")], Vec3(0.21388, 5.61436, -2.58160), 1e-5, "head end");
  expect_near(f.end[bone(s, "rfingers")], Vec3(-1.09300, 2.81041, -2.59974), 1e-5, "rfingers");
}

TEST(A3Reference, ForwardKinematicsGivesTheContractsNumbersOnWalkAmc) {
  const Skeleton s = course_skeleton();
  const Motion walk = course_motion(s, "walk.amc");
  ASSERT_EQ(walk.frames.size(), 148u);
  const BoneFrames f0 = fk(s, walk.frames[0]);
  expect_near(f0.start[0], Vec3(2.57906, 3.55306, -4.64220), 1e-5, "frame 0 root");
  expect_near(f0.end[bone(s, "head")], Vec3(2.65770, 5.79724, -4.31246), 1e-5, "frame 0 head");
  expect_near(f0.end[bone(s, "rfingers")], Vec3(2.06460, 2.78074, -3.81936), 1e-5,
              "frame 0 rfingers");
  const BoneFrames f147 = fk(s, walk.frames[147]);
  expect_near(f147.start[0], Vec3(2.89442, 3.54780, -0.77105), 1e-5, "frame 147 root");
  expect_near(f147.end[bone(s, "rfingers")], Vec3(2.13008, 2.81343, 0.08133), 1e-5,
              "frame 147 rfingers");
}

TEST(A3Reference, EveryBoneStartsWhereItsParentEndsAndHasItsLength) {
  const Skeleton s = course_skeleton();
  const BoneFrames f = fk(s, course_motion(s, "punch_kick.amc").frames[200]);
  for (std::size_t i = 1; i < s.bones.size(); ++i) {
    EXPECT_EQ(f.start[i], f.end[s.bones[i].parent]) << s.bones[i].name;
    EXPECT_NEAR((f.end[i] - f.start[i]).norm(), s.bones[i].L * s.bones[i].d.norm(), 1e-12)
        << s.bones[i].name;
  }
}

// ----- T3: the time map -----

skeleton::TimeWarp uniform(int n, int m) { return {n, m, -1, -1}; }
skeleton::TimeWarp keyframe(int n, int m, int k_in, int k_out) { return {n, m, k_in, k_out}; }

TEST(A3Reference, TheTimeMapsEndsAndKeyframeLandExactly) {
  for (const skeleton::TimeWarp& w :
       {uniform(148, 200), uniform(450, 450), uniform(2, 2), uniform(2, 7), uniform(301, 17),
        keyframe(450, 450, 160, 150), keyframe(450, 450, 150, 160), keyframe(3, 3, 1, 1),
        keyframe(148, 211, 13, 190)}) {
    const std::string what =
        "N " + std::to_string(w.input_frames) + ", M " + std::to_string(w.output_frames) + ", K " +
        std::to_string(w.keyframe_in) + " -> " + std::to_string(w.keyframe_out);
    EXPECT_EQ(a3::time_map(0, w), 0.0) << what;
    EXPECT_EQ(a3::time_map(w.output_frames - 1, w), w.input_frames - 1.0) << what;
    if (w.has_keyframe()) {
      EXPECT_EQ(a3::time_map(w.keyframe_out, w), w.keyframe_in) << what;
    }
    for (int i = 1; i < w.output_frames; ++i)
      EXPECT_GT(a3::time_map(i, w), a3::time_map(i - 1, w)) << what << ", i " << i;
  }
}

TEST(A3Reference, TheTimeMapIsTheContractsExpressionInDouble) {
  // 148 -> 200 (the 2023 retiming): s(1) = 147/199, not 0 (integer division).
  EXPECT_EQ(a3::time_map(1, uniform(148, 200)), 147.0 / 199.0);
  EXPECT_EQ(a3::time_map(100, uniform(148, 200)), 100.0 * 147.0 / 199.0);
  // punch_kick 160 -> 150: before the keyframe i·160/150, after it 160 + (i − 150)·289/299.
  EXPECT_EQ(a3::time_map(75, keyframe(450, 450, 160, 150)), 80.0);
  EXPECT_EQ(a3::time_map(151, keyframe(450, 450, 160, 150)), 160.0 + 289.0 / 299.0);
}

// ----- T4: the warped posture -----

Posture warped(const Skeleton& s, const Motion& m, double time) {
  Posture p;
  a3::warped_posture(s, m, time, p);
  return p;
}

void expect_same_posture(const Skeleton& s, const Posture& got, const Posture& want,
                         const std::string& what) {
  ASSERT_EQ(got.angles.size(), s.bones.size()) << what;
  EXPECT_EQ(got.root_translation, want.root_translation) << what;
  for (std::size_t b = 0; b < s.bones.size(); ++b)
    EXPECT_TRUE(skeleton::same_rotation(skeleton::euler_to_quaternion(got.angles[b]),
                                        skeleton::euler_to_quaternion(want.angles[b]), 1e-9))
        << what << ", bone " << s.bones[b].name << ": (" << got.angles[b].transpose()
        << ") against (" << want.angles[b].transpose() << ")";
}

TEST(A3Reference, AWarpedPostureAtAnIntegerTimeIsThatInputFrame) {
  const Skeleton s = course_skeleton();
  const Motion punch = course_motion(s, "punch_kick.amc");
  const skeleton::TimeWarp w = keyframe(450, 450, 160, 150);
  int integers = 0;
  for (int i = 0; i < w.output_frames; ++i) {
    const double time = a3::time_map(i, w);
    if (time != std::floor(time)) continue;
    ++integers;
    expect_same_posture(s, warped(s, punch, time), punch.frames[static_cast<int>(time)],
                        "output frame " + std::to_string(i));
  }
  EXPECT_GE(integers, 10) << "0, 15, 30, …, 150 and the last frame";
}

TEST(A3Reference, AWarpedPostureHalfwayIsTheSlerpAndTheLerp) {
  const Skeleton s = course_skeleton();
  const Motion walk = course_motion(s, "walk.amc");
  const Posture p = warped(s, walk, 10.25);
  const Posture &l = walk.frames[10], &r = walk.frames[11];
  EXPECT_EQ(p.root_translation, 0.75 * l.root_translation + 0.25 * r.root_translation);
  const int humerus = bone(s, "rhumerus");
  const skeleton::Quaternion want =
      skeleton::slerp(skeleton::euler_to_quaternion(l.angles[humerus]),
                      skeleton::euler_to_quaternion(r.angles[humerus]), 0.25);
  EXPECT_TRUE(
      skeleton::same_rotation(skeleton::euler_to_quaternion(p.angles[humerus]), want, 1e-9));
  EXPECT_EQ(p.angles[bone(s, "lhipjoint")], Vec3::Zero()) << "a bone without channels";
}

// ----- B1: the blend -----

TEST(A3Reference, TheBlendKeepsAsPrefixMovesBsSuffixAndMixesTheWindow) {
  const Skeleton s = course_skeleton();
  const Motion walk = course_motion(s, "walk.amc");
  const Motion run = course_motion(s, "running.amc");
  const skeleton::Blend k{127, 1, 20};
  Motion out;
  a3::blend_motions(s, walk, run, k, out);
  ASSERT_EQ(out.frames.size(), static_cast<std::size_t>(k.a) + run.frames.size() - k.b);
  EXPECT_EQ(out.fps, walk.fps);
  for (int i = 0; i < k.a; ++i) EXPECT_EQ(out.frames[i].angles, walk.frames[i].angles) << i;
  Vec3 delta = walk.frames[k.a].root_translation - run.frames[k.b].root_translation;
  delta.y() = 0.0;
  for (std::size_t j = k.b + k.window; j < run.frames.size(); ++j) {
    const Posture& o = out.frames[k.a + j - k.b];
    EXPECT_EQ(o.angles, run.frames[j].angles) << j;
    EXPECT_EQ(o.root_translation, run.frames[j].root_translation + delta) << j;
  }
  for (int w = 0; w < k.window; ++w) {
    const double weight = (1.0 - portable::cos(3.14159265358979323846 * (w + 1) / k.window)) / 2.0;
    const Vec3 b_moved = run.frames[k.b + w].root_translation + delta;
    const Vec3 want = (1.0 - weight) * walk.frames[k.a + w].root_translation + weight * b_moved;
    expect_near(out.frames[k.a + w].root_translation, want, 1e-15,
                "window frame " + std::to_string(w));
  }
  // The last window frame has weight 1: B' itself, as a rotation.
  Posture last_b = run.frames[k.b + k.window - 1];
  last_b.root_translation += delta;
  for (std::size_t b = 0; b < s.bones.size(); ++b)
    if (s.bones[b].channels.empty()) last_b.angles[b] = Vec3::Zero();
  const Posture& last = out.frames[k.a + k.window - 1];
  expect_near(last.root_translation, last_b.root_translation, 1e-12, "w = 1 translation");
  for (std::size_t b = 0; b < s.bones.size(); ++b)
    EXPECT_TRUE(skeleton::same_rotation(skeleton::euler_to_quaternion(last.angles[b]),
                                        skeleton::euler_to_quaternion(last_b.angles[b]), 1e-9))
        << s.bones[b].name;
}

}  // namespace
}  // namespace jelly
