// `jelly run`, `check` and `params` on the cloth scenes (assignment A2): the summary of decision 12
// (the cloth's centre of mass with its pins, kinetic energy, largest speed, lowest y, and each
// sphere), bad cloth input named with its key, and the stability detector: no alarm at the
// course's step, a blow-up caught at a large one (decision 15).
#include <gtest/gtest.h>

#include "run_jelly.hpp"
#include "test_folder.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using Result = jelly::testing::CliResult;
Result jelly(const std::string& arguments) { return jelly::testing::run_jelly(arguments); }
std::string scene(const std::string& name) { return jelly::testing::scene_path(name); }

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

class CliCloth : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = jelly::testing::fresh_test_folder("cli-cloth"); }
  fs::path dir_;
};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  for (std::string c; std::getline(ss, c, ',');) out.push_back(c);
  return out;
}

TEST_F(CliCloth, RunSummarisesTheClothAndEverySphere) {
  if (std::string(JELLY_CLI_TASKS) != "solutions")
    GTEST_SKIP() << "needs the reference springs and integrators";
  const fs::path sum = dir_ / "sum.csv";
  const Result r = jelly("run " + scene("cloth-2022.toml") +
                         " --duration 0.05 --every 100 --summary " + sum.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(has(r.output, "cloth of 625 particles, 3502 springs, 4 spheres")) << r.output;
  EXPECT_TRUE(has(r.output, "lowest y")) << r.output;
  for (const char* s : {"sphere 0 (dynamic)", "sphere 3 (dynamic)"})
    EXPECT_TRUE(has(r.output, s)) << s << "\n" << r.output;
  std::ifstream in(sum);
  std::string header, first, last, line;
  std::getline(in, header);
  std::string expected = "time,com_x,com_y,com_z,kinetic,potential,spring,max_speed,lowest_y";
  for (int k = 0; k < 4; ++k)
    for (const char* c : {"_x", "_y", "_z", "_vx", "_vy", "_vz"})
      expected += ",sphere" + std::to_string(k) + c;
  EXPECT_EQ(header, expected);
  std::getline(in, first);
  last = first;
  long rows = 1;
  while (std::getline(in, line)) last = line, ++rows;
  EXPECT_EQ(rows, 6);  // steps 0, 100, ..., 500
  const auto a = split(first), b = split(last);
  ASSERT_EQ(a.size(), 9u + 24u);
  ASSERT_EQ(b.size(), 9u + 24u);
  // At t = 0 the cloth is flat at y = 0 and the spheres at rest at y = 1; by 0.05 s the cloth has
  // sagged (pinned corners included in its centre of mass) and the spheres fallen ½ g t².
  EXPECT_EQ(std::stod(a[2]), 0.0);
  EXPECT_EQ(std::stod(a[8]), 0.0);
  EXPECT_LT(std::stod(b[2]), -1e-3);
  EXPECT_LT(std::stod(b[8]), std::stod(b[2]));
  EXPECT_EQ(std::stod(a[10]), 1.0);  // sphere 0's y
  EXPECT_NEAR(std::stod(b[10]), 1.0 - 0.5 * 9.8 * 0.05 * 0.05, 1e-3);
  EXPECT_NEAR(std::stod(b[13]), -9.8 * 0.05, 1e-2);  // sphere 0's vy
}

TEST_F(CliCloth, AKinematicSphereFollowsItsSchedule) {
  const fs::path sum = dir_ / "sum.csv";
  const Result r = jelly("run " + scene("cloth-2024.toml") +
                         " --duration 0.75 --every 7500 --quiet --summary " + sum.string());
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream in(sum);
  std::string line, last;
  while (std::getline(in, line)) last = line;
  const auto b = split(last);
  ASSERT_EQ(b.size(), 9u + 6u);
  // 2 m/s along x from 0.5 s: 0.25 s later the centre is at x = 0.5, moving at (2, 0, 0).
  EXPECT_NEAR(std::stod(b[9]), 0.5, 1e-9);
  EXPECT_EQ(std::stod(b[10]), 0.0);
  EXPECT_EQ(std::stod(b[12]), 2.0);
}

TEST_F(CliCloth, CheckNamesPinsAndSpheres) {
  if (std::string(JELLY_CLI_TASKS) != "solutions")
    GTEST_SKIP() << "needs the reference spring builders";
  const Result r = jelly("check " + scene("cloth-2022.toml"));
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(has(r.output, "cloth-2022: valid. 629 particles, 3502 springs")) << r.output;
  EXPECT_TRUE(has(r.output, "(4 pinned)")) << r.output;
  EXPECT_TRUE(has(r.output, "4 spheres [0 dynamic r 0.5, 125 kg]")) << r.output;
  const Result k = jelly("check " + scene("cloth-curtain.toml"));
  ASSERT_EQ(k.code, 0) << k.output;
  EXPECT_TRUE(has(k.output, "(25 pinned)")) << k.output;
  const Result f = jelly("check " + scene("cloth-flag.toml"));
  EXPECT_TRUE(has(f.output, "[0 kinematic r 0.5]")) << f.output;
}

TEST_F(CliCloth, ParamsAndSetSpeakTheClothKeys) {
  const Result p = jelly("params " + scene("cloth-2024.toml"));
  ASSERT_EQ(p.code, 0) << p.output;
  for (const char* k : {"body.air_drag", "collision.friction", "collision.push_out",
                        "sphere.0.schedule", "0: 0,0,0; 0.5: 2,0,0; 1: -2,0,0; 1.5: 0,0,0"})
    EXPECT_TRUE(has(p.output, k)) << k;
  const fs::path sum = dir_ / "sum.csv";
  const Result bad = jelly("run " + scene("cloth-2024.toml") +
                           " --set collision.push_out=2 --summary " + sum.string());
  EXPECT_EQ(bad.code, 2);
  EXPECT_TRUE(has(bad.output, "collision.push_out: must be a number ≤ 1")) << bad.output;
  EXPECT_FALSE(fs::exists(sum));
  const Result typo = jelly("run " + scene("cloth-2024.toml") + " --set sphere.0.radus=1");
  EXPECT_EQ(typo.code, 2);
  EXPECT_TRUE(has(typo.output, "did you mean \"sphere.0.radius\"")) << typo.output;
}

// Decision 15: the course's implicit Euler (predictor-corrector) is stable on cloth-2022 only up
// to h ≈ 1.27e-4. At 1.5e-4 the detector stops the run (exit 3); at the course's 1e-4 it does
// not fire over the same time (docs/cloth.md has the full runs of every integrator).
TEST_F(CliCloth, TheDetectorCatchesImplicitEulerAboveItsLimitAndNotBelow) {
  if (std::string(JELLY_CLI_TASKS) != "solutions")
    GTEST_SKIP() << "needs the reference integrators";
  const std::string base =
      "run " + scene("cloth-2022.toml") + " --integrator implicit_euler --duration 0.3 --quiet";
  const Result ok = jelly(base + " --dt 1e-4");
  EXPECT_EQ(ok.code, 0) << ok.output;
  const Result blown = jelly(base + " --dt 1.5e-4");
  EXPECT_EQ(blown.code, 3) << blown.output;
  EXPECT_TRUE(has(blown.output, "unstable: Implicit Euler")) << blown.output;
}

}  // namespace
