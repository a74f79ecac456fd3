// `jelly run` and `jelly check` of the course's skeleton scenes (scenes/hw2-*.toml), in process,
// through a TaskTable whose skeleton slots this file fills with a small implementation written
// from the kinematics contract (§3–§5) with Eigen's angle-axis rotations and slerp: an independent
// check of the kind's frame loop, its summary and the contract's §8 numbers. Also: each argument
// the contract calls an error, once the motion is read; a slot not filled; a task that returns a
// wrong answer. And the skeleton's accuracy study (skeleton_study.cpp), on the same table.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "jelly/body_kind.hpp"
#include "jelly/params.hpp"
#include "jelly/scene.hpp"
#include "jelly/skeleton/rotation.hpp"
#include "jelly/skeleton/skeleton_files.hpp"
#include "jelly/skeleton_player.hpp"
#include "jelly/skeleton_scene.hpp"
#include "jelly/skeleton_tasks.hpp"
#include "jelly/task_probe.hpp"
#include "skeleton_study.hpp"
#include "test_folder.hpp"

namespace jelly {
namespace {

namespace fs = std::filesystem;
using skeleton::BoneFrames;
using skeleton::Mat3;
using skeleton::Motion;
using skeleton::Posture;
using skeleton::Skeleton;

const fs::path kSource(JELLY_SOURCE_DIR);

// ----- the test's implementation of the slots, from the contract -----

Eigen::Quaterniond test_quaternion(const Vec3& degrees) {
  const Vec3 r = degrees * (3.14159265358979323846 / 180.0);
  return Eigen::AngleAxisd(r.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(r.y(), Vec3::UnitY()) *
         Eigen::AngleAxisd(r.x(), Vec3::UnitX());
}

Mat3 test_e(const Vec3& degrees) { return test_quaternion(degrees).toRotationMatrix(); }

// §4, recursively from the root.
void fk_bone(const Skeleton& s, const Posture& p, int i, BoneFrames& out) {
  const skeleton::Bone& b = s.bones[i];
  if (b.parent < 0) {
    out.rotation[i] = test_e(p.angles[i]);
    out.start[i] = out.end[i] = p.root_translation;
  } else {
    out.rotation[i] = out.rotation[b.parent] * b.C * test_e(p.angles[i]);
    out.start[i] = out.end[b.parent];
    out.end[i] = out.start[i] + b.L * out.rotation[i] * b.d;
  }
  for (int c : b.children) fk_bone(s, p, c, out);
}

void test_fk(const Skeleton& s, const Posture& p, BoneFrames& out) {
  out.rotation.assign(s.bones.size(), Mat3::Identity());
  out.start.assign(s.bones.size(), Vec3::Zero());
  out.end.assign(s.bones.size(), Vec3::Zero());
  fk_bone(s, p, 0, out);
}

double test_time_map(int i, const skeleton::TimeWarp& w) {
  const int n = w.input_frames, m = w.output_frames;
  if (!w.has_keyframe()) return static_cast<double>(i) * (n - 1) / (m - 1);
  if (i <= w.keyframe_out) return static_cast<double>(i) * w.keyframe_in / w.keyframe_out;
  return w.keyframe_in + static_cast<double>(i - w.keyframe_out) * (n - 1 - w.keyframe_in) /
                             (m - 1 - w.keyframe_out);
}

Posture mix(const Skeleton& s, const Posture& l, const Posture& r, double t) {
  Posture out = Posture::zero(s.bones.size());
  out.root_translation = (1.0 - t) * l.root_translation + t * r.root_translation;
  for (std::size_t b = 0; b < s.bones.size(); ++b)
    if (!s.bones[b].channels.empty())
      out.angles[b] = skeleton::quaternion_to_euler(
          test_quaternion(l.angles[b]).slerp(t, test_quaternion(r.angles[b])));
  return out;
}

void test_warped_posture(const Skeleton& s, const Motion& in, double time, Posture& out) {
  const int last = static_cast<int>(in.frames.size()) - 1;
  const int l = static_cast<int>(time);
  const int r = std::min(l + 1, last);
  out = mix(s, in.frames[l], in.frames[r], time - l);
}

void test_blend(const Skeleton& s, const Motion& a, const Motion& b, const skeleton::Blend& k,
                Motion& out) {
  Vec3 delta = a.frames[k.a].root_translation - b.frames[k.b].root_translation;
  delta.y() = 0.0;
  out.fps = a.fps;
  out.frames.assign(a.frames.begin(), a.frames.begin() + k.a);
  for (std::size_t j = k.b; j < b.frames.size(); ++j) {
    Posture moved = b.frames[j];
    moved.root_translation += delta;
    const int i = static_cast<int>(j) - k.b;
    if (i < k.window) {
      const double w = (1.0 - std::cos(3.14159265358979323846 * (i + 1) / k.window)) / 2.0;
      moved = mix(s, a.frames[k.a + i], moved, w);
    }
    out.frames.push_back(moved);
  }
}

TaskTable test_table() {
  TaskTable t;
  SkeletonTasks& k = skeleton_tasks(t);
  k.local_rotation = test_e;
  k.forward_kinematics = test_fk;
  k.time_map = test_time_map;
  k.warped_posture = test_warped_posture;
  k.blend_motions = test_blend;
  return t;
}

// ----- running a scene and reading its summary -----

const BodyKindModule& kind() { return *find_body_kind("skeleton"); }

SceneSpec course_scene(const std::string& name) {
  const SceneResult r = load_scene(kSource / "scenes" / name);
  EXPECT_TRUE(r) << (r.error ? r.error->text() : "");
  return r ? *r.scene : SceneSpec{};
}

struct Summary {
  std::string header;
  std::vector<std::vector<std::string>> rows;
  double number(std::size_t row, std::size_t column) const {
    return std::strtod(rows.at(row).at(column).c_str(), nullptr);
  }
  Vec3 point(int frame, int bone, int bones, int first_column) const {
    const std::size_t r = static_cast<std::size_t>(frame) * bones + bone;
    return {number(r, first_column), number(r, first_column + 1), number(r, first_column + 2)};
  }
};

class SkeletonPlay : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = jelly::testing::fresh_test_folder("skeleton"); }
  std::string summary_path() const { return (dir_ / "summary.csv").string(); }

  // Plays `scene` with the test's table (or `tasks`) and reads the summary it wrote.
  Summary play(const SceneSpec& scene, const TaskTable& tasks = test_table(), long every = 1) {
    report_ = kind().play(scene, tasks, {summary_path(), every});
    Summary s;
    std::ifstream in(summary_path());
    std::getline(in, s.header);
    for (std::string line; std::getline(in, line);) {
      std::vector<std::string> cells;
      std::stringstream ss(line);
      for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
      s.rows.push_back(cells);
    }
    return s;
  }

  fs::path dir_;
  std::string report_;
};

constexpr int kBones = 31;
constexpr const char* kColumns = "frame,bone,name,start_x,start_y,start_z,end_x,end_y,end_z";

void expect_near(const Vec3& got, const Vec3& expected, const std::string& what) {
  // The contract prints 5 decimals: within half a unit of the last digit.
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], expected[k], 5.01e-6) << what << " " << k;
}

int bone(const Skeleton& s, const char* name) { return *s.find(name); }

Skeleton course_skeleton() {
  return *skeleton::read_asf(kSource / "data" / "mocap" / "skeleton.asf", 0.2).skeleton;
}

TEST_F(SkeletonPlay, Fk2022GivesTheContractsReferenceNumbers) {
  const Summary s = play(course_scene("hw2-fk-2022.toml"));
  EXPECT_EQ(s.header, kColumns);
  ASSERT_EQ(s.rows.size(), 148u * kBones);
  EXPECT_EQ(s.rows[0][0], "0");
  EXPECT_EQ(s.rows[0][2], "root");
  EXPECT_EQ(s.rows.back()[0], "147");
  const Skeleton sk = course_skeleton();
  const int head = bone(sk, "head"), fingers = bone(sk, "rfingers");
  EXPECT_EQ(s.rows[head][2], "head");
  // Contract §8, walk.amc.
  expect_near(s.point(0, 0, kBones, 3), {2.57906, 3.55306, -4.64220}, "frame 0 root start");
  expect_near(s.point(0, 0, kBones, 6), {2.57906, 3.55306, -4.64220}, "frame 0 root end");
  expect_near(s.point(0, head, kBones, 6), {2.65770, 5.79724, -4.31246}, "frame 0 head end");
  expect_near(s.point(0, fingers, kBones, 6), {2.06460, 2.78074, -3.81936}, "frame 0 rfingers");
  expect_near(s.point(147, 0, kBones, 3), {2.89442, 3.54780, -0.77105}, "frame 147 root");
  expect_near(s.point(147, fingers, kBones, 6), {2.13008, 2.81343, 0.08133}, "frame 147 rfingers");
  EXPECT_NE(report_.find("played 148 of 148 frames"), std::string::npos) << report_;
  EXPECT_NE(report_.find("wrote 4588 summary rows"), std::string::npos) << report_;
}

TEST_F(SkeletonPlay, SummaryNumbersReadBackToTheSameDoubles) {
  const Summary s = play(course_scene("hw2-fk-2022.toml"));
  const Skeleton sk = course_skeleton();
  const Motion m = *skeleton::read_amc(kSource / "data" / "mocap" / "walk.amc", sk).motion;
  BoneFrames f;
  test_fk(sk, m.frames[5], f);
  for (int b = 0; b < kBones; ++b) {
    EXPECT_EQ(s.point(5, b, kBones, 3), f.start[b]) << b;
    EXPECT_EQ(s.point(5, b, kBones, 6), f.end[b]) << b;
  }
}

// The positions and local quaternions of output frame `out` equal those of input frame `in`.
void expect_frame_is_input(const Summary& s, int out, const Motion& m, int in, const Skeleton& sk) {
  BoneFrames f;
  test_fk(sk, m.frames[in], f);
  for (int b = 0; b < kBones; ++b) {
    const std::string what = "output " + std::to_string(out) + " bone " + std::to_string(b);
    EXPECT_LT((s.point(out, b, kBones, 6) - f.end[b]).norm(), 1e-9) << what;
    const std::size_t r = static_cast<std::size_t>(out) * kBones + b;
    const skeleton::Quaternion q(s.number(r, 9), s.number(r, 10), s.number(r, 11), s.number(r, 12));
    EXPECT_TRUE(
        skeleton::same_rotation(q, skeleton::euler_to_quaternion(m.frames[in].angles[b]), 1e-9))
        << what;
  }
}

TEST_F(SkeletonPlay, Warp2022MapsFirstKeyframeAndLastFramesExactly) {
  const Summary s = play(course_scene("hw2-warp-2022.toml"));
  EXPECT_EQ(s.header, std::string(kColumns) + ",qw,qx,qy,qz");
  ASSERT_EQ(s.rows.size(), 450u * kBones);
  const Skeleton sk = course_skeleton();
  const Motion m = *skeleton::read_amc(kSource / "data" / "mocap" / "punch_kick.amc", sk).motion;
  expect_frame_is_input(s, 0, m, 0, sk);      // s(0) = 0
  expect_frame_is_input(s, 150, m, 160, sk);  // the keyframe
  expect_frame_is_input(s, 449, m, 449, sk);  // s(M − 1) = N − 1
  EXPECT_EQ(s.rows.back()[0], "449");
}

TEST_F(SkeletonPlay, UniformRetimingOfTheWalkHas200Frames) {
  const Summary s = play(course_scene("hw2-retime-2023.toml"));
  ASSERT_EQ(s.rows.size(), 200u * kBones);
  const Skeleton sk = course_skeleton();
  const Motion m = *skeleton::read_amc(kSource / "data" / "mocap" / "walk.amc", sk).motion;
  expect_frame_is_input(s, 0, m, 0, sk);
  expect_frame_is_input(s, 199, m, 147, sk);
}

TEST_F(SkeletonPlay, BlendPlaysAThenTheWindowThenMovedB) {
  const Summary s = play(course_scene("hw2-blend-2022.toml"));
  ASSERT_EQ(s.rows.size(), 274u * kBones);  // a + |B| − b = 127 + 148 − 1
  const Skeleton sk = course_skeleton();
  const Motion a = *skeleton::read_amc(kSource / "data" / "mocap" / "walk.amc", sk).motion;
  expect_frame_is_input(s, 126, a, 126, sk);
  // The window's last frame has weight 1: B'[b + W − 1] = B[20] moved by Δ.
  const Motion b = *skeleton::read_amc(kSource / "data" / "mocap" / "running.amc", sk).motion;
  Vec3 delta = a.frames[127].root_translation - b.frames[1].root_translation;
  delta.y() = 0.0;
  EXPECT_LT((s.point(146, 0, kBones, 3) - (b.frames[20].root_translation + delta)).norm(), 1e-9);
}

TEST_F(SkeletonPlay, DurationAndEveryChooseTheFramesWritten) {
  SceneSpec scene = course_scene("hw2-fk-2022.toml");
  ASSERT_FALSE(set_parameter(scene, "simulation.duration", "0.5").has_value());
  Summary s = play(scene);
  EXPECT_EQ(s.rows.size(), 61u * kBones) << "frames i with i / 120 ≤ 0.5";
  EXPECT_NE(report_.find("played 61 of 148 frames"), std::string::npos) << report_;
  s = play(course_scene("hw2-fk-2022.toml"), test_table(), 10);
  ASSERT_EQ(s.rows.size(), 15u * kBones);  // frames 0, 10, …, 140
  EXPECT_EQ(s.rows[kBones][0], "10");
}

// ----- only what the scene calls for (contract §10): every slot's calls, counted -----

struct SlotCalls {
  int local_rotation = 0, forward_kinematics = 0, time_map = 0, warped_posture = 0, blend = 0;
};
SlotCalls g_calls;

/// The test's table with every slot wrapped in a counter of its calls (g_calls).
TaskTable counting_table() {
  g_calls = SlotCalls{};
  TaskTable t;
  SkeletonTasks& k = skeleton_tasks(t);
  k.local_rotation = [](const Vec3& d) {
    ++g_calls.local_rotation;
    return test_e(d);
  };
  k.forward_kinematics = [](const Skeleton& s, const Posture& p, BoneFrames& out) {
    ++g_calls.forward_kinematics;
    test_fk(s, p, out);
  };
  k.time_map = [](int i, const skeleton::TimeWarp& w) {
    ++g_calls.time_map;
    return test_time_map(i, w);
  };
  k.warped_posture = [](const Skeleton& s, const Motion& in, double time, Posture& out) {
    ++g_calls.warped_posture;
    test_warped_posture(s, in, time, out);
  };
  k.blend_motions = [](const Skeleton& s, const Motion& a, const Motion& b,
                       const skeleton::Blend& blend, Motion& out) {
    ++g_calls.blend;
    test_blend(s, a, b, blend, out);
  };
  return t;
}

TEST_F(SkeletonPlay, PlaybackCallsForwardKinematicsOncePerFrameAndNoWarp) {
  play(course_scene("hw2-fk-2022.toml"), counting_table());
  EXPECT_EQ(g_calls.forward_kinematics, 148);  // walk.amc's frames
  EXPECT_EQ(g_calls.time_map, 0);
  EXPECT_EQ(g_calls.warped_posture, 0);
  EXPECT_EQ(g_calls.blend, 0);
  EXPECT_EQ(g_calls.local_rotation, 0);  // FK's own business, not the frame loop's
}

TEST_F(SkeletonPlay, AWarpCallsEachTaskOncePerOutputFrame) {
  play(course_scene("hw2-warp-2022.toml"), counting_table());
  EXPECT_EQ(g_calls.time_map, 450);
  EXPECT_EQ(g_calls.warped_posture, 450);
  EXPECT_EQ(g_calls.forward_kinematics, 450);  // one drawing of each output frame
  EXPECT_EQ(g_calls.blend, 0);
  play(course_scene("hw2-retime-2023.toml"), counting_table());
  EXPECT_EQ(g_calls.time_map, 200);
  EXPECT_EQ(g_calls.warped_posture, 200);
  EXPECT_EQ(g_calls.forward_kinematics, 200);
}

TEST_F(SkeletonPlay, ABlendIsMadeOnceAndDrawnOncePerFrame) {
  play(course_scene("hw2-blend-2022.toml"), counting_table());
  EXPECT_EQ(g_calls.blend, 1);
  EXPECT_EQ(g_calls.forward_kinematics, 274);  // a + |B| − b = 127 + 148 − 1
  EXPECT_EQ(g_calls.time_map, 0);
  EXPECT_EQ(g_calls.warped_posture, 0);
}

TEST_F(SkeletonPlay, AShortenedRunComputesOnlyTheFramesItPlays) {
  SceneSpec scene = course_scene("hw2-warp-2022.toml");
  ASSERT_FALSE(set_parameter(scene, "simulation.duration", "0.5").has_value());
  kind().play(scene, counting_table(), {"", 1});  // no summary: the same work
  EXPECT_EQ(g_calls.time_map, 61);                // frames i with i / 120 ≤ 0.5, not M = 450
  EXPECT_EQ(g_calls.warped_posture, 61);
  EXPECT_EQ(g_calls.forward_kinematics, 61);
}

TEST_F(SkeletonPlay, APlotSeriesReadsItsMotionAndASliderLeavesTheOriginalAlone) {
  const TaskTable tasks = counting_table();
  SkeletonPlayer p(course_scene("hw2-warp-2022.toml"), skeleton_tasks(tasks));
  const int rhand = bone(p.skeleton(), "rhand"), n = p.frame_count();
  ASSERT_EQ(n, 450);
  const std::vector<float> original = bone_series(p, rhand, BoneQuantity::Rx, true);
  const std::vector<float> warped = bone_series(p, rhand, BoneQuantity::Rx, false);
  ASSERT_EQ(original.size(), 450u);
  ASSERT_EQ(warped.size(), 450u);
  for (int i : {0, 160, 300, 449}) {
    EXPECT_EQ(original[i], static_cast<float>(p.input().frames[i].angles[rhand].x())) << i;
    EXPECT_EQ(warped[i], static_cast<float>(p.output().frames[i].angles[rhand].x())) << i;
  }
  g_calls = {};
  const std::vector<float> height = bone_series(p, rhand, BoneQuantity::Height, false);
  EXPECT_EQ(g_calls.forward_kinematics, n);  // one forward kinematics a frame, nothing else
  EXPECT_EQ(g_calls.warped_posture, 0);
  EXPECT_EQ(height[300], static_cast<float>(p.output_frames(300)->end[rhand].y()));

  skeleton::TimeWarp w = p.warp();
  w.keyframe_in += 20;  // the slider moves: the warped series changes, the original's does not
  ASSERT_EQ(p.set_warp(w), "");
  EXPECT_EQ(bone_series(p, rhand, BoneQuantity::Rx, true), original);
  EXPECT_NE(bone_series(p, rhand, BoneQuantity::Rx, false), warped);
}

// ----- the accuracy study: slerp against the Euler lerp (docs/skeleton-studies.md) -----

TEST(SkeletonStudy, RotationAngleIsTheAngleBetweenTheRotations) {
  using bodies::rotation_angle_degrees;
  EXPECT_NEAR(rotation_angle_degrees(Vec3(0, 0, 0), Vec3(0, 0, 30)), 30.0, 1e-12);
  EXPECT_NEAR(rotation_angle_degrees(Vec3(10, 20, 30), Vec3(370, 20, 30)), 0.0, 1e-12);  // q, −q
  EXPECT_NEAR(rotation_angle_degrees(Vec3(0, 0, 0), Vec3(1e-7, 0, 0)), 1e-7, 1e-15);
  EXPECT_NEAR(rotation_angle_degrees(Vec3(0, 0, 0), Vec3(0, 0, 190)), 170.0, 1e-12);
}

TEST_F(SkeletonPlay, TheStudyComparesSlerpWithTheEulerLerpOnTheScenesWarp) {
  const SceneSpec scene = course_scene("hw2-warp-2022.toml");
  const bodies::SkeletonInputs in = bodies::read_skeleton_inputs(scene);
  const skeleton::TimeWarp warp{450, 450, 160, 150};
  const bodies::InterpolationStudy st =
      bodies::study_interpolation(in, warp, skeleton_tasks(test_table()), 1);
  ASSERT_EQ(st.bones.size(), 29u);  // lhipjoint and rhipjoint have no channels
  ASSERT_EQ(st.frame_max_degrees.size(), 450u);
  int whole = 0;
  for (int i = 0; i < 450; ++i)
    if (st.frame_s[i] == std::floor(st.frame_s[i])) {
      ++whole;
      EXPECT_LT(st.frame_max_degrees[i], 1e-9) << "an input frame itself, output frame " << i;
    }
  EXPECT_EQ(whole, 12);
  EXPECT_GT(st.max_degrees, 1e-3) << "the shortcut is not slerp";
  EXPECT_LT(st.max_degrees, 1.0) << "neighbouring frames at 120 fps";
  EXPECT_GT(st.mean_degrees, 0.0);
  EXPECT_LT(st.mean_degrees, st.max_degrees);
  // The reported worst bone and frame give the reported angle, recomputed here.
  Posture slerped = Posture::zero(kBones), lerped;
  test_warped_posture(in.skeleton, in.motion, st.frame_s[st.worst_frame], slerped);
  bodies::euler_lerp_posture(in.motion, st.frame_s[st.worst_frame], lerped);
  EXPECT_EQ(
      bodies::rotation_angle_degrees(slerped.angles[st.worst_bone], lerped.angles[st.worst_bone]),
      st.max_degrees);
  bodies::euler_lerp_posture(in.motion, 10.25, lerped);
  EXPECT_EQ(lerped.angles[5],
            0.75 * in.motion.frames[10].angles[5] + 0.25 * in.motion.frames[11].angles[5]);
}

TEST_F(SkeletonPlay, TheStudyWritesItsTablesAndRefusesAPlayback) {
  const std::string prefix = (dir_ / "study").string();
  const std::string report =
      bodies::study_skeleton_scene(course_scene("hw2-retime-2023.toml"), test_table(), prefix, 1);
  EXPECT_NE(report.find("148 -> 200 frames, 29 bones with channels"), std::string::npos) << report;
  const auto lines = [](const std::string& path) {
    std::ifstream in(path);
    int n = 0;
    for (std::string line; std::getline(in, line);) ++n;
    return n;
  };
  EXPECT_EQ(lines(prefix + "-bones.csv"), 1 + 29);
  EXPECT_EQ(lines(prefix + "-frames.csv"), 1 + 200);
  try {
    bodies::study_skeleton_scene(course_scene("hw2-fk-2022.toml"), test_table(), prefix, 1);
    ADD_FAILURE() << "a playback has no warp to study";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("body.mode = \"playback\""), std::string::npos)
        << e.what();
  }
}

// ----- what is refused -----

std::string play_error(const SceneSpec& scene, const TaskTable& tasks, const std::string& path) {
  try {
    kind().play(scene, tasks, {path, 1});
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an error";
  return "";
}

TEST_F(SkeletonPlay, ASlotTheTasksDoNotFillIsAnErrorNamingItAndWritesNothing) {
  std::string e = play_error(course_scene("hw2-fk-2022.toml"), TaskTable{}, summary_path());
  EXPECT_NE(e.find("needs the task forward_kinematics"), std::string::npos) << e;
  EXPECT_NE(e.find("SkeletonTasks::forward_kinematics is null"), std::string::npos) << e;
  EXPECT_FALSE(fs::exists(summary_path()));
  TaskTable fk_only;
  skeleton_tasks(fk_only).forward_kinematics = test_fk;
  e = play_error(course_scene("hw2-warp-2022.toml"), fk_only, summary_path());
  EXPECT_NE(e.find("a skeleton warp needs the task time_map"), std::string::npos) << e;
  skeleton_tasks(fk_only).time_map = test_time_map;
  e = play_error(course_scene("hw2-warp-2022.toml"), fk_only, summary_path());
  EXPECT_NE(e.find("needs the task warped_posture"), std::string::npos) << e;
  e = play_error(course_scene("hw2-blend-2022.toml"), fk_only, summary_path());
  EXPECT_NE(e.find("a skeleton blend needs the task blend_motions"), std::string::npos) << e;
  EXPECT_FALSE(fs::exists(summary_path()));
}

TEST_F(SkeletonPlay, ASummaryThatCannotBeWrittenIsAnOutputError) {
  const std::string path = (dir_ / "no-such-folder" / "summary.csv").string();
  EXPECT_THROW(kind().play(course_scene("hw2-fk-2022.toml"), test_table(), {path, 1}),
               std::system_error);
}

void short_fk(const Skeleton&, const Posture&, BoneFrames& out) { out = BoneFrames{}; }
double past_the_end(int i, const skeleton::TimeWarp& w) { return i + w.input_frames; }

TEST_F(SkeletonPlay, ATaskThatReturnsAWrongAnswerIsAnErrorNamingIt) {
  TaskTable t = test_table();
  skeleton_tasks(t).forward_kinematics = short_fk;
  std::string e = play_error(course_scene("hw2-fk-2022.toml"), t, summary_path());
  EXPECT_NE(e.find("task forward_kinematics, output frame 0"), std::string::npos) << e;
  EXPECT_NE(e.find("the skeleton has 31 bones"), std::string::npos) << e;
  t = test_table();
  skeleton_tasks(t).time_map = past_the_end;
  e = play_error(course_scene("hw2-warp-2022.toml"), t, summary_path());
  EXPECT_NE(e.find("task time_map, output frame 0: returned s = 450; expected 0 ≤ s ≤ N − 1 = 449"),
            std::string::npos)
      << e;
}

// ----- inverse kinematics: what the stubs return, bones the skeleton lacks -----

std::string check_with_ik(const std::string& key, const std::string& value);

// A4's stubs (assignments/a4/): each returns nothing useful.
std::vector<int> stub_chain(const Skeleton&, int, int) { return {}; }
void stub_jacobian(const Skeleton&, const BoneFrames&, const std::vector<int>&,
                   skeleton::Matrix3X&) {}
void stub_least_squares(const skeleton::Matrix3X&, const Vec3&, skeleton::VectorX&) {}
skeleton::IkResult stub_iterate(const Skeleton&, const std::vector<int>&, const Vec3&,
                                const skeleton::IkSettings&, const skeleton::IkOps&, Posture&) {
  return {};
}
void stub_clamp(const Skeleton&, const std::vector<int>&, Posture&) {}
skeleton::IkResult stub_solve(const skeleton::IkSettings&, const skeleton::IkOps&, Posture&) {
  return {};
}
std::vector<int> chain_of_the_hand(const Skeleton&, int, int end) { return {end}; }

TaskTable stub_ik_table() {
  TaskTable t = test_table();
  SkeletonTasks& k = skeleton_tasks(t);
  k.ik_chain = stub_chain;
  k.ik_jacobian = stub_jacobian;
  k.least_squares = stub_least_squares;
  k.ik_iterate = stub_iterate;
  k.clamp_to_limits = stub_clamp;
  k.ik_solve = stub_solve;
  return t;
}

TEST_F(SkeletonPlay, AnIkSceneWithTheStubsIsAnErrorNamingTheTaskNeverACrash) {
  if (!fs::exists(kSource / "scenes" / "hw3-ik.toml")) GTEST_SKIP() << "no A4 scenes";
  std::string e = play_error(course_scene("hw3-ik.toml"), test_table(), summary_path());
  EXPECT_NE(e.find("needs the task ik_chain"), std::string::npos) << e;
  TaskTable t = stub_ik_table();
  e = play_error(course_scene("hw3-ik.toml"), t, summary_path());
  EXPECT_NE(e.find("task ik_chain, output frame 0, chain 0 (lowerback -> rfingers): returned an "
                   "empty chain"),
            std::string::npos)
      << e;
  // A chain given, the stubs' ik_solve leaves the error unmeasured (∞) and the posture alone.
  skeleton_tasks(t).ik_chain = chain_of_the_hand;
  kind().play(course_scene("hw3-ik.toml"), t, {summary_path(), 1});
  std::ifstream in(summary_path());
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first,
            "# frame 0 chain 0 lowerback -> rfingers: target (-0.0692501, 3.85358, -1.63441), "
            "updates 0, stable false, error inf");
}

TEST_F(SkeletonPlay, AnIkChainsBonesAndFrameAreCheckedAgainstTheFiles) {
  if (!fs::exists(kSource / "scenes" / "hw3-ik.toml")) GTEST_SKIP() << "no A4 scenes";
  std::string e = check_with_ik("chain.0.end", "rfinger");
  EXPECT_NE(e.find("chain.0.end: no bone \"rfinger\" in "), std::string::npos) << e;
  EXPECT_NE(e.find("(did you mean \"rfingers\"?)"), std::string::npos) << e;
  EXPECT_NE(e.find("its bones: root, lhipjoint, "), std::string::npos) << e;
  EXPECT_NE(e.find("hw3-ik.toml"), std::string::npos) << e;
  e = check_with_ik("body.frame", "1");
  EXPECT_NE(e.find("body.frame: must be a frame of the motion, 0 ≤ frame < 1"), std::string::npos)
      << e;
  e = check_with_ik("", "");
  EXPECT_NE(e.find("chain 0 lowerback -> rfingers (bones 11 -> 29): target (-0.0692501, 3.85358, "
                   "-1.63441)"),
            std::string::npos)
      << e;
}

// `jelly check`'s report, or its first error, of the scene with `key` set to `value`.
std::string check_with(const std::string& scene_name, const std::string& key,
                       const std::string& value) {
  SceneSpec scene = course_scene(scene_name);
  if (!key.empty()) {
    const auto err = set_parameter(scene, key, value);
    EXPECT_FALSE(err.has_value()) << err->text();
  }
  try {
    return kind().check_frames(scene);
  } catch (const std::runtime_error& e) {
    return std::string("error: ") + e.what();
  }
}

std::string check_with_ik(const std::string& key, const std::string& value) {
  return check_with("hw3-ik.toml", key, value);
}

TEST_F(SkeletonPlay, CheckReportsTheCountsOfTheCourseFiles) {
  std::string r = check_with("hw2-fk-2022.toml", "", "");
  EXPECT_EQ(r.rfind("hw2-fk-2022: valid. skeleton ", 0), 0u) << r;
  EXPECT_NE(r.find("data/mocap/skeleton.asf: 31 bones, 62 channels (scale 0.2)"), std::string::npos)
      << r;
  EXPECT_NE(r.find("data/mocap/walk.amc: 148 frames at 120 fps"), std::string::npos) << r;
  r = check_with("hw2-warp-2022.toml", "", "");
  EXPECT_NE(r.find("punch_kick.amc: 450 frames"), std::string::npos) << r;
  EXPECT_NE(r.find("warp: 450 -> 450 frames, keyframe 160 -> 150"), std::string::npos) << r;
  r = check_with("hw2-blend-2022.toml", "", "");
  EXPECT_NE(r.find("running.amc: 148 frames"), std::string::npos) << r;
  EXPECT_NE(r.find("blend: a 127, b 1, window 20: 274 frames"), std::string::npos) << r;
}

TEST_F(SkeletonPlay, CheckListsTheNotesOfWhatTheReadersSkipped) {
  // CMU's bodymass after line 20 of the course's skeleton; an unknown AMC header keyword.
  std::ifstream asf(kSource / "data" / "mocap" / "skeleton.asf");
  std::ofstream noted(dir_ / "noted.asf");
  int n = 0;
  for (std::string line; std::getline(asf, line);)
    noted << line << "\n" << (++n == 20 ? "     bodymass 3.2\n" : "");
  noted.close();
  std::ifstream walk(kSource / "data" / "mocap" / "walk.amc");
  std::ofstream amc(dir_ / "noted.amc");
  amc << ":SPEED fast\n" << walk.rdbuf();
  amc.close();
  SceneSpec scene = course_scene("hw2-fk-2022.toml");
  ASSERT_FALSE(set_parameter(scene, "body.asf", (dir_ / "noted.asf").generic_string()));
  ASSERT_FALSE(set_parameter(scene, "body.amc", (dir_ / "noted.amc").generic_string()));
  const std::string r = kind().check_frames(scene);
  EXPECT_NE(r.find("2 notes (skipped sections and keys):"), std::string::npos) << r;
  EXPECT_NE(r.find((dir_ / "noted.asf").generic_string() + ":21: "), std::string::npos) << r;
  EXPECT_NE(r.find("bodymass"), std::string::npos) << r;
  EXPECT_NE(r.find((dir_ / "noted.amc").generic_string() + ":1: "), std::string::npos) << r;
}

TEST_F(SkeletonPlay, ArgumentsTheContractCallsErrorsNameTheSceneKeyAndBound) {
  const std::string warp = (kSource / "scenes" / "hw2-warp-2022.toml").string();
  std::string e = check_with("hw2-warp-2022.toml", "body.keyframe_in", "449");
  EXPECT_EQ(e.rfind("error: " + warp +
                        ": body.keyframe_in: must satisfy 0 < keyframe_in < N − 1 "
                        "= 449 (punch_kick.amc has 450 frames",
                    0),
            0u)
      << e;
  e = check_with("hw2-warp-2022.toml", "body.keyframe_out", "449");
  EXPECT_NE(e.find(": body.keyframe_out: must satisfy 0 < keyframe_out < M − 1 = 449"),
            std::string::npos)
      << e;
  e = check_with("hw2-warp-2022.toml", "body.frames", "100");
  EXPECT_NE(e.find("body.keyframe_out: must satisfy 0 < keyframe_out < M − 1 = 99"),
            std::string::npos)
      << e;
  e = check_with("hw2-blend-2022.toml", "body.a", "129");
  EXPECT_NE(e.find("body.a: must satisfy a + window ≤ the motion's frames (walk.amc has 148 "
                   "frames; kinematics contract §5), got 129 + 20 = 149"),
            std::string::npos)
      << e;
  e = check_with("hw2-blend-2022.toml", "body.b", "200");
  EXPECT_NE(e.find("body.b: must satisfy b + window"), std::string::npos) << e;
  e = check_with("hw2-fk-2022.toml", "body.amc", "../data/mocap/missing.amc");
  EXPECT_EQ(
      e.rfind("error: " + (kSource / "scenes" / "hw2-fk-2022.toml").string() + ": body.amc: ", 0),
      0u)
      << e;
  EXPECT_NE(e.find("data/mocap/missing.amc"), std::string::npos) << e;
}

TEST_F(SkeletonPlay, AMotionOfTwoFramesRetimesAndRefusesAKeyframe) {
  // walk.amc's header and its first two frames (AMC frames 1 and 2).
  const fs::path two = dir_ / "two_frames.amc";
  {
    std::ifstream in(kSource / "data" / "mocap" / "walk.amc");
    std::ofstream out(two);
    for (std::string line; std::getline(in, line) && line != "3";) out << line << "\n";
  }
  SceneSpec scene = course_scene("hw2-retime-2023.toml");
  ASSERT_FALSE(set_parameter(scene, "body.amc", two.string()).has_value());
  ASSERT_FALSE(set_parameter(scene, "body.frames", "9").has_value());
  const Summary s = play(scene, counting_table());
  ASSERT_EQ(s.rows.size(), 9u * kBones);
  EXPECT_EQ(g_calls.warped_posture, 9);
  const Skeleton sk = course_skeleton();
  const Motion m = *skeleton::read_amc(two, sk).motion;
  ASSERT_EQ(m.frames.size(), 2u);
  expect_frame_is_input(s, 0, m, 0, sk);
  expect_frame_is_input(s, 8, m, 1, sk);
  // 0 < keyframe_in < N − 1 = 1 has no solution: a keyframe warp of two frames is an error.
  skeleton_scene(scene).keyframe_in = 1;  // the pair at once (--set checks one key at a time)
  skeleton_scene(scene).keyframe_out = 4;
  try {
    kind().check_frames(scene);
    ADD_FAILURE() << "a keyframe on a motion of two frames";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(
        std::string(e.what()).find("body.keyframe_in: must satisfy 0 < keyframe_in < N − 1 = 1"),
        std::string::npos)
        << e.what();
  }
}

TEST_F(SkeletonPlay, ABrokenMotionFileGivesItsFirstErrorWithFileAndLine) {
  std::ifstream walk(kSource / "data" / "mocap" / "walk.amc");
  std::ofstream broken(dir_ / "broken.amc");
  int n = 0;
  for (std::string line; std::getline(walk, line);)
    broken << (++n == 7 ? std::string("upperback 1.5 x 0.3") : line) << "\n";
  broken.close();
  SceneSpec scene = course_scene("hw2-fk-2022.toml");
  ASSERT_FALSE(set_parameter(scene, "body.amc", (dir_ / "broken.amc").generic_string()));
  ASSERT_FALSE(set_parameter(scene, "body.asf",
                             (kSource / "data" / "mocap" / "skeleton.asf").generic_string()));
  std::string e;
  try {
    kind().check_frames(scene);
  } catch (const std::runtime_error& err) {
    e = err.what();
  }
  EXPECT_EQ(e.rfind((dir_ / "broken.amc").generic_string() + ":7: ", 0), 0u) << e;
}

// ----- the probes of the slots (jelly probe) -----

Mat3 stub_rotation(const Vec3&) { return Mat3::Identity(); }
void stub_fk(const Skeleton& s, const Posture&, BoneFrames& out) {
  out.rotation.assign(s.bones.size(), Mat3::Identity());
  out.start.assign(s.bones.size(), Vec3::Zero());
  out.end.assign(s.bones.size(), Vec3::Zero());
}
double stub_time_map(int, const skeleton::TimeWarp&) { return 0.0; }
void stub_warped_posture(const Skeleton& s, const Motion&, double, Posture& out) {
  out = Posture::zero(s.bones.size());
}
void stub_blend(const Skeleton&, const Motion&, const Motion&, const skeleton::Blend&, Motion&) {}

TEST(SkeletonProbe, TellsTheContractsTasksFromStubsAndMissingOnes) {
  const std::vector<std::string_view> all = probe_slots();
  TaskTable stubs;
  SkeletonTasks& k = skeleton_tasks(stubs);
  k.local_rotation = stub_rotation;
  k.forward_kinematics = stub_fk;
  k.time_map = stub_time_map;
  k.warped_posture = stub_warped_posture;
  k.blend_motions = stub_blend;
  for (const char* slot :
       {"local_rotation", "forward_kinematics", "time_map", "warped_posture", "blend_motions"}) {
    EXPECT_NE(std::find(all.begin(), all.end(), slot), all.end()) << slot;
    const TaskStatus done = probe_slot(slot, "A3.T", "task", test_table());
    EXPECT_TRUE(done.implemented) << slot << ": " << done.evidence;
    const TaskStatus stub = probe_slot(slot, "A3.T", "task", stubs);
    EXPECT_FALSE(stub.implemented) << slot << ": " << stub.evidence;
    const TaskStatus none = probe_slot(slot, "A3.T", "task", TaskTable{});
    EXPECT_FALSE(none.implemented) << slot;
    EXPECT_EQ(none.evidence, "function missing from the task table") << slot;
  }
  EXPECT_EQ(probe_slot("time_map", "A3.T3", "time map", test_table()).evidence,
            "s(2) = 1 for a uniform warp of 3 to 5 frames");
  // A wrong-sized answer counts as implemented and is never read past.
  TaskTable wrong = test_table();
  skeleton_tasks(wrong).forward_kinematics = short_fk;
  EXPECT_TRUE(probe_slot("forward_kinematics", "A3.T2", "fk", wrong).implemented);
}

}  // namespace
}  // namespace jelly
