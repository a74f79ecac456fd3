// `jelly check`, `jelly params` and `jelly run` of the skeleton scenes (scenes/hw2-*.toml) as a
// user runs them. The run's numbers are checked in process (tests/skeleton/test_skeleton_play.cpp);
// here: the command line's counts, messages and exit codes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "jelly/manifest.hpp"
#include "run_jelly.hpp"
#include "test_folder.hpp"

namespace fs = std::filesystem;

namespace {

using Result = jelly::testing::CliResult;
Result jelly(const std::string& arguments) { return jelly::testing::run_jelly(arguments); }
std::string scene(const std::string& name) { return jelly::testing::scene_path(name); }
bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

class CliSkeleton : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = jelly::testing::fresh_test_folder("cli-skeleton"); }
  std::string out() const { return (dir_ / "out.csv").string(); }
  fs::path dir_;
};

TEST_F(CliSkeleton, CheckReadsTheFilesAndReportsTheirCounts) {
  const Result r = jelly("check " + scene("hw2-warp-2022.toml"));
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(has(r.output, "hw2-warp-2022: valid. skeleton ")) << r.output;
  EXPECT_TRUE(has(r.output, "skeleton.asf: 31 bones, 62 channels (scale 0.2)")) << r.output;
  EXPECT_TRUE(has(r.output, "punch_kick.amc: 450 frames at 120 fps")) << r.output;
  EXPECT_TRUE(has(r.output, "warp: 450 -> 450 frames, keyframe 160 -> 150")) << r.output;
  EXPECT_FALSE(has(r.output, "integrator")) << "a skeleton has no step size: " << r.output;
}

TEST_F(CliSkeleton, CheckGivesABrokenMotionsFirstErrorWithFileAndLine) {
  std::ifstream walk(std::string(JELLY_SOURCE_DIR) + "/data/mocap/walk.amc");
  std::ofstream broken(dir_ / "broken.amc");
  int n = 0;
  for (std::string line; std::getline(walk, line);)
    broken << (++n == 12 ? std::string("rhumerus 1 2") : line) << "\n";
  broken.close();
  std::ofstream(dir_ / "broken.toml")
      << "# a walk whose motion file is broken\n[scene]\nname = \"broken\"\ndescription = \"x\"\n\n"
         "[body]\ntype = \"skeleton\"\nasf = \""
      << fs::path(JELLY_SOURCE_DIR).generic_string() << "/data/mocap/skeleton.asf\"\n"
      << "amc = \"broken.amc\"\n";
  const Result r = jelly("check " + (dir_ / "broken.toml").string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(has(r.output, "jelly check: " + (dir_ / "broken.amc").generic_string() + ":12: "))
      << r.output;
}

TEST_F(CliSkeleton, CheckRefusesAKeyframeOutsideTheMotionNamingSceneAndKey) {
  const Result r = jelly("check " + scene("hw2-warp-2022.toml") + " --set body.keyframe_in=460");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(has(r.output,
                  "hw2-warp-2022.toml: body.keyframe_in: must satisfy 0 < keyframe_in "
                  "< N − 1 = 449"))
      << r.output;
}

TEST_F(CliSkeleton, ParamsListTheSkeletonKeys) {
  const Result r = jelly("params " + scene("hw2-warp-2022.toml"));
  EXPECT_EQ(r.code, 0) << r.output;
  for (const char* key : {"body.asf", "body.amc", "body.scale", "body.fps", "body.mode",
                          "body.frames", "body.keyframe_in", "body.keyframe_out"})
    EXPECT_TRUE(has(r.output, key)) << key;
  EXPECT_FALSE(has(r.output, "body.n ")) << "no cube key";
}

TEST_F(CliSkeleton, RunHelpNamesTheSkeletonColumns) {
  const Result r = jelly("run --help");
  EXPECT_TRUE(has(r.output, "frame,bone,name")) << r.output;
}

TEST_F(CliSkeleton, RunRefusesOutBecauseASkeletonHasNoParticles) {
  const Result r = jelly("run " + scene("hw2-fk-2022.toml") + " --out " + out());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(has(r.output, "--out writes particles, and a skeleton scene has none")) << r.output;
  EXPECT_FALSE(fs::exists(out()));
}

// Whether an assignment of this tree (every one is built into jelly) simulates the skeleton's
// warps: its manifest claims them ("skeleton" or "skeleton:warp").
bool an_assignment_simulates_the_skeleton() {
  for (const jelly::AssignmentManifest& m :
       jelly::find_assignments(fs::path(JELLY_SOURCE_DIR) / "assignments"))
    if (m.claims("skeleton", "warp")) return true;
  return false;
}

// Without such an assignment the run names the first slot it needs and why there is none, and
// writes nothing.
TEST_F(CliSkeleton, RunWithoutSkeletonTasksNamesTheMissingTask) {
  if (an_assignment_simulates_the_skeleton()) GTEST_SKIP() << "an assignment fills the slots";
  const Result r = jelly("run " + scene("hw2-warp-2022.toml") + " --summary " + out());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(has(r.output, "jelly run: a skeleton warp needs the task forward_kinematics"))
      << r.output;
  EXPECT_TRUE(has(r.output, "no assignment in this program simulates a skeleton body")) << r.output;
  EXPECT_FALSE(fs::exists(out()));
}

// With one, its reference plays the warp: a row per frame and bone. (The stubs' answers need not
// be usable: a forward kinematics that fills nothing is an error naming the task.)
TEST_F(CliSkeleton, RunWithSkeletonTasksWritesARowPerFrameAndBone) {
  if (!an_assignment_simulates_the_skeleton()) GTEST_SKIP() << "no assignment fills the slots";
  if (std::string(JELLY_CLI_TASKS) != "solutions") GTEST_SKIP() << "needs the reference tasks";
  const Result r = jelly("run " + scene("hw2-warp-2022.toml") + " --summary " + out());
  EXPECT_EQ(r.code, 0) << r.output;
  std::ifstream in(out());
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "frame,bone,name,start_x,start_y,start_z,end_x,end_y,end_z,qw,qx,qy,qz");
  int rows = 0;
  for (std::string line; std::getline(in, line);) ++rows;
  EXPECT_EQ(rows, 450 * 31);
}

// The forward kinematics scene through the reference: kinematics contract §8's frame 0 of walk.amc
// in the summary (rfingers, bone 29, ends at (2.06460, 2.78074, −3.81936)).
TEST_F(CliSkeleton, RunOfTheFkSceneWritesTheContractsNumbers) {
  if (!an_assignment_simulates_the_skeleton()) GTEST_SKIP() << "no assignment fills the slots";
  if (std::string(JELLY_CLI_TASKS) != "solutions") GTEST_SKIP() << "needs the reference tasks";
  const Result r = jelly("run " + scene("hw2-fk-2022.toml") + " --summary " + out());
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(has(r.output, "played 148 of 148 frames")) << r.output;
  std::ifstream in(out());
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header, "frame,bone,name,start_x,start_y,start_z,end_x,end_y,end_z");
  bool found = false;
  while (std::getline(in, line))
    if (line.rfind("0,29,rfingers,", 0) == 0) {
      found = true;
      std::istringstream row(line.substr(14));
      double v[6] = {};
      char comma = 0;
      for (int k = 0; k < 6; ++k) row >> v[k] >> comma;
      EXPECT_NEAR(v[3], 2.06460, 1e-5) << line;
      EXPECT_NEAR(v[4], 2.78074, 1e-5) << line;
      EXPECT_NEAR(v[5], -3.81936, 1e-5) << line;
    }
  EXPECT_TRUE(found) << "no row of rfingers at frame 0";
}

}  // namespace
