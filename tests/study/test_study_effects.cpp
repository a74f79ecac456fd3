// `jelly study effects`, run as a user runs it, on small cubes and short runs: the measures on
// cases whose answer is known (free fall: no impact and no volume change; a cube at rest in no
// gravity is at rest from t = 0; a drop onto a plane touches when the fall says it must and never
// rises above where it started), a direction docs/parameters.md reports (stiffer: less cave-in),
// the outputs, determinism, and the refusals of bad input.
#include <gtest/gtest.h>

#include "run_jelly.hpp"
#include "study_files.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using Result = jelly::testing::CliResult;
using Rows = std::vector<std::map<std::string, std::string>>;
using jelly::testing::artifacts;
using jelly::testing::read;
using jelly::testing::read_csv;
Result jelly(const std::string& arguments) { return jelly::testing::run_jelly(arguments); }
std::string scene(const std::string& name) { return jelly::testing::scene_path(name); }
double d(const std::map<std::string, std::string>& row, const std::string& column) {
  return std::stod(row.at(column));
}

/// Runs `jelly study effects ARGS --quiet --out DIR/NAME` and returns its CSV rows.
Rows effects(const std::string& name, const std::string& args) {
  const fs::path dir = artifacts("effects-" + name);
  const Result r = jelly("study effects " + args + " --quiet --out " + (dir / name).string());
  EXPECT_EQ(r.code, 0) << r.output;
  return read_csv(dir / (name + ".csv"));
}

TEST(StudyEffects, FreeFallHasNoImpactAndKeepsItsVolume) {
  // No terrain: nothing touches, so every impact measure is nan; the cube falls as one piece.
  const Rows rows =
      effects("free-fall", scene("free-fall.toml") +
                               " --set body.n=4 --duration 0.5 --integrators rk4,symplectic_euler");
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) {
    for (const char* column : {"contact_time", "impact_speed", "turn_time",
                               "peak_speed_after_impact", "com_apex", "bounce_height", "rest_time"})
      EXPECT_EQ(row.at(column), "nan") << column;
    EXPECT_NEAR(d(row, "rest_volume"), 64.0, 1e-12);  // edge 4 m
    EXPECT_LT(std::abs(d(row, "cave_in_max")), 1e-12);
    EXPECT_EQ(row.at("stable"), "true");
    EXPECT_EQ(row.at("particles"), "64");
  }
  // RK4 keeps the energy of a free fall to rounding (it is exact for constant acceleration).
  EXPECT_LT(std::abs(d(rows[0], "dissipated_fraction")), 1e-9);
  EXPECT_EQ(d(rows[0], "force_evaluations"), 4 * 500);
  EXPECT_EQ(d(rows[1], "force_evaluations"), 500);
}

TEST(StudyEffects, RestVolumeIsTheCubesVolumeInAnyOrientation) {
  const Rows rows = effects(
      "volume", scene("free-fall.toml") +
                    " --set body.n=5 --set gravity.enabled=false --set body.rotation_degrees=37"
                    " --duration 0.6 --param body.edge --values 1,2.5");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_NEAR(d(rows[0], "rest_volume"), 1.0, 1e-13);
  EXPECT_NEAR(d(rows[1], "rest_volume"), 2.5 * 2.5 * 2.5, 1e-12);
  for (const auto& row : rows) {
    // Nothing moves: no cave-in, at rest from the start, no energy lost but rounding (a rotated
    // cube's springs are an ulp off their rest lengths: residual energies of ~1e-29 J, whose
    // exact value depends on how the rotation is rounded).
    EXPECT_LT(std::abs(d(row, "cave_in_max")), 1e-12);
    EXPECT_EQ(d(row, "rest_time"), 0.0);
    EXPECT_LT(std::abs(d(row, "energy_dissipated")), 1e-20);
  }
}

TEST(StudyEffects, DropOnAPlaneTouchesWhenTheFallSaysAndNeverRisesAboveItsStart) {
  // Centre at y = 9, edge 4, plane y = -1, ε = 0.01: the lowest face reaches y = -0.99 after a
  // fall of 7.99 m, at t = sqrt(2 · 7.99 / 9.8) = 1.2770 s, at 12.51 m/s (symplectic Euler is one
  // step off the exact fall).
  const Rows rows = effects(
      "drop", scene("course-2021-plane.toml") +
                  " --set body.n=4 --duration 3 --param terrain.*.restitution --values 0,1");
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) {
    EXPECT_NEAR(d(row, "contact_time"), std::sqrt(2 * 7.99 / 9.8), 2e-3);
    EXPECT_NEAR(d(row, "impact_speed"), 9.8 * std::sqrt(2 * 7.99 / 9.8), 0.02);
    EXPECT_GT(d(row, "turn_time"), d(row, "contact_time"));
    EXPECT_LE(d(row, "com_apex"), 9.0);  // restitution ≤ 1 and damped springs add no energy
    EXPECT_GT(d(row, "bounce_height"), 0.0);
    EXPECT_GT(d(row, "cave_in_max"), 0.0);
    EXPECT_GT(d(row, "energy_dissipated"), 0.0);
  }
  // Restitution acts on the touching layer only: the same fall, the same first contact.
  EXPECT_EQ(rows[0].at("contact_time"), rows[1].at("contact_time"));
}

TEST(StudyEffects, StifferSpringsCaveInLess) {
  // docs/parameters.md, claim b i, on a small cube: every spring type's ks at once.
  const Rows rows = effects(
      "stiff", scene("course-2021-plane.toml") +
                   " --set body.n=4 --duration 2 --param springs.*.ks --values 500,2000,8000");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].at("key"), "springs.*.ks");
  EXPECT_GT(d(rows[0], "cave_in_max"), d(rows[1], "cave_in_max"));
  EXPECT_GT(d(rows[1], "cave_in_max"), d(rows[2], "cave_in_max"));
}

TEST(StudyEffects, WritesEveryOutputAndIsDeterministicButForTheTimings) {
  const fs::path dir = artifacts("effects-outputs");
  const std::string args =
      "study effects " + scene("course-2021-plane.toml") +
      " --set body.n=3 --duration 1.5 --param body.center.y --values 5,9 --integrators "
      "explicit_euler,midpoint --out ";
  const Result a = jelly(args + (dir / "a").string());
  ASSERT_EQ(a.code, 0) << a.output;
  EXPECT_NE(a.output.find("[4/4] body.center.y=9 midpoint h=0.001: stable"), std::string::npos)
      << a.output;
  const Result b = jelly(args + (dir / "b").string() + " --quiet");
  ASSERT_EQ(b.code, 0) << b.output;
  EXPECT_EQ(b.output, "") << "--quiet prints nothing";
  for (const char* ext : {".csv", ".md", ".dat", ".gp", "-time.dat", "-time.gp"})
    EXPECT_TRUE(fs::exists(dir / (std::string("a") + ext))) << ext;
  if (std::system("gnuplot --version > /dev/null 2>&1") == 0) {
    for (const char* ext : {".svg", "-time.svg"})
      EXPECT_NE(read(dir / (std::string("a") + ext)).find("<svg"), std::string::npos) << ext;
  }
  const Rows ra = read_csv(dir / "a.csv"), rb = read_csv(dir / "b.csv");
  ASSERT_EQ(ra.size(), 4u);
  ASSERT_EQ(rb.size(), 4u);
  for (std::size_t i = 0; i < ra.size(); ++i) {
    auto x = ra[i], y = rb[i];
    for (auto* m : {&x, &y}) m->erase("wall_s"), m->erase("wall_s_per_sim_s");
    EXPECT_EQ(x, y) << "row " << i;
  }
  // The drop height moved the centre: the higher drop touches later.
  EXPECT_EQ(ra[0].at("value"), "5");
  EXPECT_GT(d(ra[1], "contact_time"), d(ra[0], "contact_time"));
  const std::string md = read(dir / "a.md");
  EXPECT_NE(md.find("| integrator | value | h [s] | stable |"), std::string::npos) << md;
}

TEST(StudyEffects, TheDetectorStopsARunAndMarksIt) {
  // Explicit Euler at 1 ms with very strong dampers is far outside its stable region.
  const Rows rows =
      effects("unstable", scene("course-2021-plane.toml") +
                              " --set body.n=4 --duration 1 --integrators explicit_euler "
                              "--param springs.*.kd --values 60,3000");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].at("stable"), "true");
  EXPECT_EQ(rows[1].at("stable"), "false");
  EXPECT_GT(d(rows[1], "detected_at"), 0.0);
  EXPECT_LT(d(rows[1], "sim_s"), 1.0) << "the run stops where the detector fired";
}

TEST(StudyEffects, RefusesBadInputAndWritesNothing) {
  const fs::path dir = artifacts("effects-bad");
  const std::string out = " --out " + (dir / "x").string();
  const std::string plane = scene("course-2021-plane.toml");
  struct Case {
    std::string args, says;
  };
  const Case cases[] = {
      {plane + " --param springs.structral.ks --values 1,2",
       "did you mean \"springs.structural.ks\"?"},
      {plane + " --param springs.*.ks --values 100,-1", "springs.structural.ks"},
      {plane + " --param springs.*.kz --values 1",
       "springs.*.kz: matches no parameter of this scene"},
      {plane + " --param body.center --values 0,9,0", "separate vector values with ';'"},
      {plane + " --param body.n --values 3,x", "body.n"},
      {plane + " --param body.n", "needs --values"},
      {plane + " --values 1,2", "nothing to sweep"},
      {plane + " --integrators rk5", "unknown integrator 'rk5'"},
      {plane + " --integrators rk4 --repeats 0", "--repeats"},
      {plane + " --integrators rk4 --rest-speed -1", "--rest-speed"},
      {plane + " --integrators rk4 --bogus", "unknown option --bogus"},
      {scene("no-such-scene.toml") + " --integrators rk4", "no-such-scene.toml"},
  };
  for (const Case& c : cases) {
    const Result r = jelly("study effects " + c.args + out);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.says), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_FALSE(fs::exists(dir / "x.csv")) << c.args;
  }
  const Result help = jelly("study effects --help");
  EXPECT_EQ(help.code, 0);
  EXPECT_NE(help.output.find("cave-in      largest 1 - V(t)/V(0)"), std::string::npos)
      << help.output;
}

}  // namespace

namespace {

/// The rows of the first Markdown table after `marker` in `text`, as maps from header to cell.
Rows markdown_table_after(const std::string& text, const std::string& marker) {
  Rows rows;
  std::size_t at = text.find(marker);
  if (at == std::string::npos) return rows;
  std::istringstream lines(text.substr(at));
  std::vector<std::string> header;
  auto cells = [](const std::string& line) {
    std::vector<std::string> out;
    std::stringstream ss(line.substr(1));
    for (std::string c; std::getline(ss, c, '|');) {
      const auto b = c.find_first_not_of(' '), e = c.find_last_not_of(' ');
      out.push_back(b == std::string::npos ? "" : c.substr(b, e - b + 1));
    }
    return out;
  };
  bool in_table = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("|", 0) != 0) {
      if (in_table) break;
      continue;
    }
    if (!in_table) {
      header = cells(line);
      in_table = true;
    } else if (line.rfind("|---", 0) != 0) {
      const auto c = cells(line);
      std::map<std::string, std::string> row;
      for (std::size_t i = 0; i < header.size() && i < c.size(); ++i) row[header[i]] = c[i];
      rows.push_back(row);
    }
  }
  return rows;
}

TEST(StudyEffects, TheStiffnessNumbersOfDocsParametersStillHold) {
  // docs/parameters.md, claim b i: the cave-in of the n = 10 cube on the plane for the softest and
  // stiffest springs. The largest volume loss happens at the first impact (t ≈ 1.35 s), so 2 s of
  // the same run give the same maximum as the 8 s the page ran; the page prints it to 0.1 %.
  const Rows doc = markdown_table_after(read(fs::path(JELLY_SOURCE_DIR) / "docs" / "parameters.md"),
                                        "<!-- sweep ks -->");
  ASSERT_FALSE(doc.empty()) << "docs/parameters.md lost its ks table";
  const Rows rows = effects(
      "doc-ks",
      scene("course-2021-plane.toml") +
          " --duration 2 --integrators symplectic_euler --param springs.*.ks --values 500,8000");
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) {
    const auto it = std::find_if(doc.begin(), doc.end(), [&](const auto& d) {
      return d.at("integrator") == "symplectic_euler" && d.at("value") == row.at("value");
    });
    ASSERT_NE(it, doc.end()) << "no symplectic_euler row for ks " << row.at("value");
    char measured[32];
    std::snprintf(measured, sizeof measured, "%.1f %%", 100.0 * d(row, "cave_in_max"));
    EXPECT_EQ(it->at("cave-in max"), measured)
        << "ks " << row.at("value") << ": rerun tools/parameter-sweeps ks "
        << "and update docs/parameters.md";
  }
  EXPECT_GT(d(rows[0], "cave_in_max"), 2.0 * d(rows[1], "cave_in_max")) << "stiffer caves in less";
}

}  // namespace

namespace {

TEST(LectureDemos, EveryParameterTheInstructorGuideSetsExists) {
  // docs/instructor-guide.md, "Lecture demos for the parameter discussion": every `--slot-set
  // K:key=value;...` of its jelly-lab commands must still be a valid parameter of its scene, or the
  // demo fails in front of a class. Checked through `jelly params SCENE --set ...` (the viewer
  // applies the same declarations).
  const std::string guide = read(fs::path(JELLY_SOURCE_DIR) / "docs" / "instructor-guide.md");
  const std::size_t start = guide.find("### Lecture demos for the parameter discussion");
  ASSERT_NE(start, std::string::npos);
  const std::size_t open = guide.find("```sh", start), close = guide.find("```\n", open + 5);
  ASSERT_NE(close, std::string::npos);
  std::string block = guide.substr(open + 5, close - open - 5);
  // The block's shell variables, and its line continuations.
  const std::map<std::string, std::string> vars = {
      {"$S", "springs.structural"}, {"$H", "springs.shear"}, {"$B", "springs.bending"}};
  for (const auto& [name, value] : vars)
    for (std::size_t at; (at = block.find(name)) != std::string::npos;)
      block.replace(at, name.size(), value);
  for (std::size_t at; (at = block.find("\\\n")) != std::string::npos;) block.replace(at, 2, " ");
  std::istringstream lines(block);
  int commands = 0, assignments = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("$L ", 0) != 0) continue;
    ++commands;
    std::istringstream words(line.substr(3));
    std::string scene_file, word, sets;
    words >> scene_file;
    while (words >> word) {
      if (word != "--slot-set") continue;
      words >> word;
      if (!word.empty() && word.front() == '"') word = word.substr(1, word.size() - 2);
      std::stringstream parts(word.substr(word.find(':') + 1));
      for (std::string kv; std::getline(parts, kv, ';');) sets += " --set " + kv, ++assignments;
    }
    const Result r = jelly("params " + (fs::path(JELLY_SOURCE_DIR) / scene_file).string() + sets);
    EXPECT_EQ(r.code, 0) << line << "\n" << r.output;
  }
  EXPECT_GE(commands, 7) << "one command per claim";
  EXPECT_GE(assignments, 15);
}

}  // namespace
