// `jelly study accuracy` on the two-particle spring: the CSV has the documented columns, the
// observed orders are the methods' orders, unstable runs are kept and marked, the Markdown table
// and the plot are written; bad sweeps are refused. And `jelly run --auto-dt` reports its choice.
#include <gtest/gtest.h>

#include "run_jelly.hpp"
#include "study_files.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using Result = jelly::testing::CliResult;
using jelly::testing::artifacts;
using jelly::testing::read;
using jelly::testing::read_csv;
Result jelly(const std::string& arguments) { return jelly::testing::run_jelly(arguments); }
std::string scene(const std::string& name) { return jelly::testing::scene_path(name); }

TEST(StudyAccuracy, SpringSweepGivesTheMethodsOrdersAndKeepsUnstableRuns) {
  const fs::path dir = artifacts("spring");
  const std::string prefix = (dir / "spring").string();
  const Result r = jelly("study accuracy " + scene("two-particle-spring.toml") +
                         " --duration 1 --h-max 0.01 --levels 4 --integrators "
                         "explicit_euler,midpoint,rk4,backward_euler --quiet --out " +
                         prefix);
  ASSERT_EQ(r.code, 0) << r.output;
  const auto rows = read_csv(prefix + ".csv");
  ASSERT_EQ(rows.size(), 16u);
  for (const char* column : {"integrator", "h", "stable", "error_final", "error_rms",
                             "wall_s_per_sim_s", "force_evaluations", "order_rms", "order_final"})
    EXPECT_TRUE(rows[0].count(column)) << column;
  std::map<std::string, std::vector<double>> orders;
  for (const auto& row : rows) {
    const std::string k = row.at("integrator");
    const double h = std::stod(row.at("h"));
    // Force evaluations per step: 1, 2, 4 and 1 (+ CG) over T = 1 s.
    const long steps = std::lround(1.0 / h);
    const long per = k == "rk4" ? 4 : k == "midpoint" ? 2 : 1;
    EXPECT_EQ(std::stol(row.at("force_evaluations")), per * steps) << k << " h " << h;
    if (row.at("order_rms") != "nan") orders[k].push_back(std::stod(row.at("order_rms")));
    // Explicit Euler grows on an undamped spring at every step: the detector flags it, and the
    // row is still there with its (finite) error.
    if (k == "explicit_euler") {
      EXPECT_EQ(row.at("stable"), "false");
      EXPECT_TRUE(std::isfinite(std::stod(row.at("error_rms"))));
    } else {
      EXPECT_EQ(row.at("stable"), "true") << k << " h " << h;
    }
  }
  // Observed orders (last pair, asymptotic): within 0.2 of 1, 2, 4, 1 (contract §9, SciML's
  // tolerance).
  EXPECT_NEAR(orders["explicit_euler"].back(), 1.0, 0.2);
  EXPECT_NEAR(orders["midpoint"].back(), 2.0, 0.2);
  EXPECT_NEAR(orders["rk4"].back(), 4.0, 0.2);
  EXPECT_NEAR(orders["backward_euler"].back(), 1.0, 0.2);

  const std::string md = read(prefix + ".md");
  EXPECT_NE(md.find("| integrator | h [s] | stable |"), std::string::npos) << md;
  EXPECT_NE(md.find("Reference: RK4 at h_ref = 7.8125e-05 s"), std::string::npos) << md;
  EXPECT_NE(md.find("**no**"), std::string::npos) << "unstable runs are marked";
  // The automatic step for each integrator; none is stable for explicit Euler on this spring.
  EXPECT_NE(md.find("Automatic step (`jelly run --auto-dt`"), std::string::npos) << md;
  EXPECT_NE(md.find("explicit_euler 0.0009804 s (17 substeps per 1/60 s frame; no step is stable)"),
            std::string::npos)
      << md;
  EXPECT_TRUE(fs::exists(prefix + ".gp"));
  EXPECT_TRUE(fs::exists(prefix + ".dat"));
  if (std::system("gnuplot --version > /dev/null 2>&1") == 0) {
    const std::string svg = read(prefix + ".svg");
    EXPECT_NE(svg.find("<svg"), std::string::npos);
    EXPECT_NE(svg.find("explicit_euler unstable"), std::string::npos) << "unstable runs drawn";
  }
}

TEST(StudyAccuracy, RefusesStepsThatDoNotDivideTheSampleInterval) {
  const fs::path dir = artifacts("bad");
  const Result r = jelly("study accuracy " + scene("two-particle-spring.toml") +
                         " --duration 1 --steps 0.003 --out " + (dir / "x").string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("sample interval 0.01 s is not a whole multiple of the step 0.003 s"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir / "x.csv"));
  const Result unknown =
      jelly("study accuracy " + scene("two-particle-spring.toml") + " --integrators rk5");
  EXPECT_EQ(unknown.code, 2);
  EXPECT_NE(unknown.output.find("unknown integrator 'rk5'"), std::string::npos) << unknown.output;
  EXPECT_EQ(jelly("study nothing").code, 2);
}

TEST(RunAutoDt, ChoosesAStableStepAndSaysWhich) {
  // Very stiff springs: explicit Euler at the scene's 1 ms is far past its limit (~6e-4 s).
  const std::string stiff = scene("hard/stiff-springs.toml");
  const Result fixed =
      jelly("run " + stiff + " --integrator explicit_euler --duration 0.4 --quiet");
  EXPECT_EQ(fixed.code, 3) << fixed.output;
  const Result autodt =
      jelly("run " + stiff + " --integrator explicit_euler --duration 0.4 --auto-dt");
  EXPECT_EQ(autodt.code, 0) << autodt.output;
  EXPECT_NE(autodt.output.find("auto step: h = 0.000297619 s (56 substeps per 0.0166667 s frame)"),
            std::string::npos)
      << autodt.output;
  // The same through the scene parameter.
  const Result param = jelly("run " + stiff +
                             " --integrator explicit_euler --duration 0.4 "
                             "--set simulation.auto_dt=true --quiet");
  EXPECT_EQ(param.code, 0) << param.output;
  EXPECT_NE(param.output.find("auto step:"), std::string::npos) << param.output;
}

}  // namespace
