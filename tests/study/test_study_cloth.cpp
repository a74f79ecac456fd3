// `jelly study effects` and `jelly study accuracy` on the cloth scenes (assignment A2), run as a
// user runs them, on small cloths and short runs: A2's manifest chooses sag, swing, sink and
// energy; a free-falling unpinned cloth sags by ½ g T² with RK4; push-out (β = 1) takes the cloth
// out of the sphere it lies on; the detector does not fire on cloth-2024 where `jelly run` does
// not (the kinematic sphere's work is counted, decision 11); accuracy errors come out finite.
#include <gtest/gtest.h>

#include "run_jelly.hpp"
#include "study_files.hpp"

#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using Result = jelly::testing::CliResult;
using Rows = std::vector<std::map<std::string, std::string>>;
using jelly::testing::artifacts;
using jelly::testing::read_csv;
Result jelly(const std::string& arguments) { return jelly::testing::run_jelly(arguments); }
std::string scene(const std::string& name) { return jelly::testing::scene_path(name); }
double d(const std::map<std::string, std::string>& row, const std::string& column) {
  return std::stod(row.at(column));
}

Rows effects(const std::string& name, const std::string& args) {
  const fs::path dir = artifacts("effects-cloth-" + name);
  const Result r = jelly("study effects " + args + " --quiet --out " + (dir / name).string());
  EXPECT_EQ(r.code, 0) << r.output;
  return read_csv(dir / (name + ".csv"));
}

TEST(StudyCloth, AFreeFallingClothSagsByHalfGTSquaredAndNeitherSwingsNorSinks) {
  // No pins, no drag, the sphere far below: every particle falls freely (RK4 is exact for it).
  const Rows rows =
      effects("free-fall", scene("cloth-2024.toml") +
                               " --set body.n=5 --set body.pins= --set body.air_drag=0"
                               " --set sphere.0.center=0,-10,0 --integrators rk4 --duration 0.2");
  ASSERT_EQ(rows.size(), 1u);
  const auto& row = rows[0];
  EXPECT_NEAR(d(row, "sag_max"), 0.5 * 9.8 * 0.2 * 0.2, 1e-12);
  EXPECT_NEAR(d(row, "sag_final"), 0.5 * 9.8 * 0.2 * 0.2, 1e-12);
  EXPECT_EQ(d(row, "swing_max"), 0.0);
  EXPECT_EQ(d(row, "sink_max"), 0.0);
  EXPECT_EQ(row.at("stable"), "true");
  EXPECT_EQ(row.at("particles"), "25");  // the cloth's 25; the kinematic sphere is no particle
  // A2 measures sag, swing, sink and energy; a cube's measures are not written.
  for (const char* absent : {"cave_in_max", "bounce_height", "impact_speed", "rest_time"})
    EXPECT_EQ(row.count(absent), 0u) << absent;
  EXPECT_EQ(row.count("energy_dissipated"), 1u);
}

TEST(StudyCloth, PushOutTakesTheClothOutOfTheSphereItLiesOn) {
  // cloth-2024 lies on the kinematic sphere: with β = 0 RK4 lets it sink into it (decision 6);
  // with β = 1 every particle found inside is put back on the surface each step.
  const Rows rows = effects("push-out", scene("cloth-2024.toml") +
                                            " --set body.n=9 --param collision.push_out"
                                            " --values 0,1 --integrators rk4 --duration 0.3");
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) EXPECT_EQ(row.at("stable"), "true");
  EXPECT_GT(d(rows[0], "sink_max"), 1e-3);  // more than a millimetre in
  EXPECT_LT(d(rows[1], "sink_max"), 0.1 * d(rows[0], "sink_max"));
  EXPECT_GT(d(rows[0], "sag_max"), 0.1);  // it hangs between its corners over the sphere
}

TEST(StudyCloth, TheStudyDetectorAgreesWithJellyRun) {
  // Explicit Euler on a 9×9 cloth-2024 is stable at the course's step (jelly run exits 0); the
  // study watches with the same settings and energy (E − W, decision 11's floor), so no alarm.
  const Result run = jelly("run " + scene("cloth-2024.toml") +
                           " --set body.n=9 --integrator explicit_euler --duration 0.3 --quiet");
  ASSERT_EQ(run.code, 0) << run.output;
  const Rows rows = effects("detector", scene("cloth-2024.toml") +
                                            " --set body.n=9 --integrators explicit_euler,rk4"
                                            " --duration 0.3");
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) EXPECT_EQ(row.at("stable"), "true") << row.at("reason");
}

TEST(StudyCloth, AccuracyOnACloth) {
  const fs::path dir = artifacts("accuracy-cloth");
  const Result r = jelly("study accuracy " + scene("cloth-2022.toml") +
                         " --set body.n=7 --integrators explicit_euler,rk4 --steps 2e-4,1e-4"
                         " --duration 0.1 --ref-factor 4 --no-ref-check --quiet --out " +
                         (dir / "acc").string());
  ASSERT_EQ(r.code, 0) << r.output;
  const Rows rows = read_csv(dir / "acc.csv");
  ASSERT_EQ(rows.size(), 4u);
  for (const auto& row : rows) {
    EXPECT_TRUE(std::isfinite(d(row, "error_rms"))) << row.at("integrator");
    EXPECT_GT(d(row, "error_rms"), 0.0);
  }
  // RK4 is far closer to the RK4 reference than explicit Euler at the same step.
  EXPECT_LT(d(rows[3], "error_rms"), 1e-2 * d(rows[1], "error_rms"));
}

}  // namespace
