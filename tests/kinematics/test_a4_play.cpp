// `jelly run` of A4's scenes (scenes/hw3-ik*.toml, scenes/ik-*.toml, kinematics contract §6, §7,
// §8, §11.14, §11.16) through the skeleton kind, in process, with A4's reference linked into its
// task table: the contract's numbers (73 and 105 updates), an unstable solve restored bit for bit,
// only the chain's channels changed, four chains solved in order, a schedule solved once per frame,
// and the summary's comment lines. Also one solve through make_ik_ops (jelly/skeleton_ik.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "course_mocap.hpp"
#include "jelly/a4/ik.hpp"
#include "jelly/a4/jacobian.hpp"
#include "jelly/a4/kinematics.hpp"
#include "jelly/a4/least_squares.hpp"
#include "jelly/a4/task_table.hpp"
#include "jelly/body_kind.hpp"
#include "jelly/scene.hpp"
#include "jelly/skeleton_ik.hpp"
#include "jelly/skeleton_scene.hpp"
#include "jelly/skeleton_tasks.hpp"
#include "test_folder.hpp"

namespace jelly {
namespace {

namespace fs = std::filesystem;

const fs::path kScenes = fs::path(JELLY_SOURCE_DIR) / "scenes";

/// hw3-ik's solve: lowerback -> rfingers to the course's ball, the course's settings.
IkSolveRequest hw3_ik_request(const skeleton::Skeleton& s) {
  IkSolveRequest request;
  request.start_bone = *s.find("lowerback");
  request.end_bone = *s.find("rfingers");
  request.target = Vec3(-0.0692501, 3.85358, -1.63441);
  return request;
}

class A4Play : public ::testing::Test {
 protected:
  /// `jelly run scenes/<name>.toml --summary` with A4's reference: the report.
  std::string run(const std::string& name) {
    const SceneResult r = load_scene(kScenes / (name + ".toml"));
    EXPECT_TRUE(r) << r.error->text();
    if (!r) return "";
    FramePlayOptions options;
    options.summary_path = (dir_ / (name + ".csv")).string();
    return find_body_kind("skeleton")->play(*r.scene, table_, options);
  }
  /// The summary's lines that start with `#`, and its other lines.
  void read_summary(const std::string& name, std::vector<std::string>& comments,
                    std::vector<std::string>& rows) {
    std::ifstream in(dir_ / (name + ".csv"));
    for (std::string line; std::getline(in, line);)
      (line[0] == '#' ? comments : rows).push_back(line);
  }
  void SetUp() override { dir_ = testing::fresh_test_folder("a4-play"); }
  TaskTable table_ = a4::task_table();
  fs::path dir_;
};

TEST_F(A4Play, Hw3IkConvergesAfter73UpdatesAndSaysSoInTheSummary) {
  const std::string report = run("hw3-ik");
  EXPECT_NE(report.find("chain 0 lowerback -> rfingers: 73 updates, stable, error 0.0009"),
            std::string::npos)
      << report;
  std::vector<std::string> comments, rows;
  read_summary("hw3-ik", comments, rows);
  ASSERT_EQ(comments.size(), 1u);
  EXPECT_EQ(comments[0].rfind("# frame 0 chain 0 lowerback -> rfingers: target (-0.0692501, "
                              "3.85358, -1.63441), updates 73, stable true, error 0.0009",
                              0),
            0u)
      << comments[0];
  ASSERT_EQ(rows.size(), 32u);  // the columns, then 31 bones
  EXPECT_EQ(rows[0], "frame,bone,name,start_x,start_y,start_z,end_x,end_y,end_z");
}

TEST_F(A4Play, Hw3IkWithLimitsConvergesAfter105Updates) {
  const std::string report = run("hw3-ik-limits");
  EXPECT_NE(report.find("chain 0 lowerback -> rfingers: 105 updates, stable"), std::string::npos)
      << report;
}

TEST_F(A4Play, AnUnreachableTargetIsRestoredBitForBit) {
  const std::string report = run("ik-unreachable");
  EXPECT_NE(report.find("1000 updates, not stable"), std::string::npos) << report;
  std::vector<std::string> comments, rows, start_comments, start_rows;
  read_summary("ik-unreachable", comments, rows);
  // The same scene with no update allowed: the posture of IK.amc's frame 0, as written.
  SceneResult r = load_scene(kScenes / "ik-unreachable.toml");
  ASSERT_TRUE(r);
  skeleton_scene(*r.scene).max_iterations = 0;
  FramePlayOptions options;
  options.summary_path = (dir_ / "start.csv").string();
  find_body_kind("skeleton")->play(*r.scene, table_, options);
  read_summary("start", start_comments, start_rows);
  EXPECT_EQ(rows, start_rows);
}

TEST_F(A4Play, AStraightArmStaysFiniteAndIsRestored) {
  const std::string report = run("ik-straight-arm");
  EXPECT_NE(report.find("chain 0 rhumerus -> rfingers: 1000 updates, not stable"),
            std::string::npos)
      << report;
  EXPECT_EQ(report.find("nan"), std::string::npos) << report;
}

TEST_F(A4Play, FourChainsAreSolvedInOrderEachStable) {
  const std::string report = run("hw3-ik-2024");
  for (const char* chain : {"chain 0 rclavicle -> rfingers", "chain 1 lclavicle -> lfingers",
                            "chain 2 rhipjoint -> rtoes", "chain 3 lhipjoint -> ltoes"})
    EXPECT_NE(report.find(std::string(chain) + ": "), std::string::npos) << chain << "\n" << report;
  EXPECT_EQ(report.find("not stable"), std::string::npos) << report;
  std::vector<std::string> comments, rows;
  read_summary("hw3-ik-2024", comments, rows);
  ASSERT_EQ(comments.size(), 4u);
  for (std::size_t c = 0; c < 4; ++c)
    EXPECT_EQ(comments[c].rfind("# frame 0 chain " + std::to_string(c) + " ", 0), 0u);
}

TEST_F(A4Play, AScheduleIsSolvedOncePerFrameWarmStarted) {
  const std::string report = run("ik-moving-target");
  EXPECT_NE(report.find("61 solves"), std::string::npos) << report;
  std::vector<std::string> comments, rows;
  read_summary("ik-moving-target", comments, rows);
  EXPECT_EQ(comments.size(), 61u);
  EXPECT_EQ(rows.size(), 1u + 61u * 31u);
  // Frame 0's target is where the fingers are: within epsilon, no update.
  EXPECT_NE(comments[0].find("updates 0, stable true"), std::string::npos) << comments[0];
}

// One solve through the framework's ops: only the chain's channels change, and a restored solve
// gives the input posture back bit for bit (§6.4, §6.5, §10).
TEST_F(A4Play, ASolveThroughTheSlotsChangesOnlyTheChainsChannels) {
  const skeleton::Skeleton s = testing::course_skeleton();
  const skeleton::Motion m = testing::course_motion(s, "IK.amc");
  IkSolveRequest request = hw3_ik_request(s);
  skeleton::Posture p = m.frames[0];
  const skeleton::IkResult r = solve_ik(s, skeleton_tasks(table_), request, p);
  EXPECT_EQ(r.updates, 73);
  EXPECT_TRUE(r.stable);
  const std::vector<int> chain = ik_chain_of(s, skeleton_tasks(table_), request);
  for (std::size_t b = 0; b < s.bones.size(); ++b) {
    if (std::find(chain.begin(), chain.end(), static_cast<int>(b)) == chain.end()) {
      EXPECT_EQ(p.angles[b], m.frames[0].angles[b]) << s.bones[b].name;
    }
  }
  EXPECT_EQ(p.root_translation, m.frames[0].root_translation);

  request.target = Vec3(0.1, 12.5, -3.0);
  skeleton::Posture q = m.frames[0];
  const skeleton::IkResult far = solve_ik(s, skeleton_tasks(table_), request, q);
  EXPECT_FALSE(far.stable);
  for (std::size_t b = 0; b < s.bones.size(); ++b)
    EXPECT_TRUE((q.angles[b].array() == m.frames[0].angles[b].array()).all()) << s.bones[b].name;
}

// The iteration asks for the end effector and the Jacobian at the same posture: the ops run the
// forward kinematics once for both, so a solve of U updates runs it U + 1 times (each update's
// posture, and the last one's), not 2U + 1, with the same 73 updates and the same final posture.
int forward_kinematics_calls = 0;

/// IkOps from A4's reference whose end_effector and jacobian each run the forward kinematics.
skeleton::IkOps fresh_frames_ops(const skeleton::Skeleton& s, const std::vector<int>& chain,
                                 const IkSolveRequest& request) {
  skeleton::IkOps ops;
  const skeleton::Skeleton* sk = &s;
  const int end = chain.front();
  ops.end_effector = [sk, end](const skeleton::Posture& p) {
    skeleton::BoneFrames f;
    a4::forward_kinematics(*sk, p, f);
    return Vec3(f.end[end]);
  };
  ops.jacobian = [sk, chain](const skeleton::Posture& p, skeleton::Matrix3X& J) {
    skeleton::BoneFrames f;
    a4::forward_kinematics(*sk, p, f);
    a4::ik_jacobian(*sk, f, chain, J);
  };
  ops.solve = [](const skeleton::Matrix3X& J, const Vec3& e, skeleton::VectorX& x) {
    a4::least_squares(J, e, x);
  };
  ops.clamp = [sk, chain](skeleton::Posture& p) { a4::clamp_to_limits(*sk, chain, p); };
  ops.iterate = [sk, chain, request, inner = ops](skeleton::Posture& p) {
    return a4::ik_iterate(*sk, chain, request.target, request.settings, inner, p);
  };
  return ops;
}
void counted_forward_kinematics(const skeleton::Skeleton& s, const skeleton::Posture& p,
                                skeleton::BoneFrames& out) {
  ++forward_kinematics_calls;
  skeleton_tasks(a4::task_table()).forward_kinematics(s, p, out);
}

TEST_F(A4Play, EachUpdateRunsTheForwardKinematicsOnce) {
  const skeleton::Skeleton s = testing::course_skeleton();
  const skeleton::Motion m = testing::course_motion(s, "IK.amc");
  const IkSolveRequest request = hw3_ik_request(s);
  TaskTable counting = a4::task_table();
  skeleton_tasks(counting).forward_kinematics = &counted_forward_kinematics;
  skeleton::Posture p = m.frames[0], q = m.frames[0];
  forward_kinematics_calls = 0;
  const skeleton::IkResult r = solve_ik(s, skeleton_tasks(counting), request, p);
  EXPECT_EQ(r.updates, 73);
  EXPECT_EQ(forward_kinematics_calls, 74);
  // The same solve through ops that run the forward kinematics for every call (as the reference's
  // tests built them by hand): the same posture and error, bit for bit.
  const std::vector<int> chain = ik_chain_of(s, skeleton_tasks(table_), request);
  const skeleton::IkOps fresh = fresh_frames_ops(s, chain, request);
  const skeleton::IkResult plain = a4::ik_solve(request.settings, fresh, q);
  EXPECT_EQ(plain.updates, 73);
  EXPECT_EQ(plain.error, r.error);
  for (std::size_t b = 0; b < s.bones.size(); ++b)
    EXPECT_TRUE((p.angles[b].array() == q.angles[b].array()).all()) << s.bones[b].name;
}

}  // namespace
}  // namespace jelly
