// `jelly run` and friends as a user runs them: bad input gives one clear message naming the file
// and key and writes nothing; an unstable run stops with exit code 3 and keeps what it wrote.
#include <gtest/gtest.h>

#include "display_column.hpp"
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
std::string file_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = jelly::testing::fresh_test_folder("cli"); }
  // Writes a scene file with one line replaced (or appended) and returns its path.
  std::string variant(const std::string& from, const std::string& old_line,
                      const std::string& new_line) {
    std::string text = file_text(scene(from));
    const auto at = text.find(old_line);
    EXPECT_NE(at, std::string::npos) << old_line;
    text.replace(at, old_line.size(), new_line);
    const fs::path p = dir_ / ("bad-" + from);
    std::ofstream(p) << text;
    return p.string();
  }
  std::string out() const { return (dir_ / "out.csv").string(); }
  fs::path dir_;
};

TEST_F(Cli, HelpDocumentsEveryOption) {
  const Result r = jelly("run --help");
  EXPECT_EQ(r.code, 0);
  for (const char* opt : {"--integrator", "--dt", "--duration", "--set", "--every", "--out",
                          "--summary", "--threads", "explicit_euler", "implicit_euler", "midpoint",
                          "rk4", "symplectic_euler", "backward_euler", "exit codes"})
    EXPECT_NE(r.output.find(opt), std::string::npos) << opt;
}

TEST_F(Cli, RunWritesTrajectoryAndSummaryWithTheDocumentedHeaders) {
  const Result r = jelly("run " + scene("course-2023.toml") + " --duration 0.05 --every 10 --out " +
                         out() + " --summary " + (dir_ / "sum.csv").string());
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream traj(out()), sum(dir_ / "sum.csv");
  std::string line;
  std::getline(traj, line);
  EXPECT_EQ(line, "frame,time,particle,x,y,z,vx,vy,vz");
  long rows = 0;
  while (std::getline(traj, line)) ++rows;
  EXPECT_EQ(rows, 6 * 1000);  // frames at steps 0, 10, …, 50 times 1000 particles
  std::getline(sum, line);
  EXPECT_EQ(line, "time,com_x,com_y,com_z,kinetic,potential,spring,max_speed");
}

// --threads splits the spring pass; the trajectory is the same to the last digit written.
TEST_F(Cli, ThreadsGiveTheSameTrajectory) {
  const std::string base =
      "run " + scene("course-2023.toml") + " --duration 0.05 --every 25 --quiet --out ";
  const Result one = jelly(base + (dir_ / "one.csv").string());
  const Result two = jelly(base + (dir_ / "two.csv").string() + " --threads 2");
  ASSERT_EQ(one.code, 0) << one.output;
  ASSERT_EQ(two.code, 0) << two.output;
  const std::string a = file_text(dir_ / "one.csv");
  EXPECT_GT(a.size(), 1000u);
  EXPECT_EQ(a, file_text(dir_ / "two.csv"));
  const Result bad = jelly(base + out() + " --threads 0");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.output.find("--threads"), std::string::npos) << bad.output;
  EXPECT_FALSE(fs::exists(out()));
}

TEST_F(Cli, SetOverridesAParameterByItsName) {
  const Result r = jelly("run " + scene("course-2023.toml") +
                         " --duration 0.01 --set body.center=-5,11,0 --set springs.shear.ks=5000 "
                         "--every 10 --summary " +
                         out());
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream sum(out());
  std::string header, first;
  std::getline(sum, header);
  std::getline(sum, first);
  // time,com_x,com_y,...: the centre of mass starts at x = −5 (the scene file says −4.8).
  const double com_x = std::stod(first.substr(first.find(',') + 1));
  EXPECT_NEAR(com_x, -5.0, 1e-12) << first;
}

TEST_F(Cli, UnknownIntegratorIsAUsageError) {
  const Result r =
      jelly("run " + scene("course-2023.toml") + " --integrator leapfrog --out " + out());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("simulation.integrator"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out()));
}

struct BadInput {
  const char* name;
  const char* old_line;
  const char* new_line;
  const char* key;  // expected in the message
};

class CliBadScene : public Cli, public ::testing::WithParamInterface<BadInput> {};

TEST_P(CliBadScene, OneClearMessageNamingFileAndKeyAndNothingWritten) {
  const BadInput& b = GetParam();
  const std::string path = variant("course-2023.toml", b.old_line, b.new_line);
  const Result r =
      jelly("run " + path + " --out " + out() + " --summary " + (dir_ / "s.csv").string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find(path), std::string::npos) << "message does not name the file:\n"
                                                    << r.output;
  EXPECT_NE(r.output.find(b.key), std::string::npos) << "message does not name " << b.key << ":\n"
                                                     << r.output;
  EXPECT_FALSE(fs::exists(out()));
  EXPECT_FALSE(fs::exists(dir_ / "s.csv"));
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, CliBadScene,
    ::testing::Values(BadInput{"malformed", "\nn = 10", "\nn = = 10", ":"},
                      BadInput{"unknown_key", "\nn = 10", "\nn = 10\nrotation_degree = 3",
                               "rotation_degree"},
                      BadInput{"wrong_type", "\nn = 10", "\nn = \"ten\"", "body.n"},
                      BadInput{"n_below_2", "\nn = 10", "\nn = 1", "body.n"},
                      BadInput{"negative_mass", "\nmass = 1.0", "\nmass = -1.0", "body.mass"},
                      BadInput{"zero_dt", "\ndt = 0.001", "\ndt = 0.0", "simulation.dt"}),
    [](const ::testing::TestParamInfo<BadInput>& p) { return std::string(p.param.name); });

// The command line (CLI11, jelly::cli::Command): a bad option is named with what it expects, the
// exit code is 2 and nothing is written; --help is the hand-written text on stdout, exit code 0.
TEST_F(Cli, BadOptionsAreNamedWithWhatTheyExpect) {
  const std::string run = "run " + scene("course-2023.toml") + " --out " + out();
  const struct {
    const char* args;
    const char* message;
  } cases[] = {
      {" --bogus", "jelly run: unknown option --bogus"},
      {" --every", "jelly run: --every needs a value (K)"},
      {" --every 1.5", "jelly run: --every: expected a whole number ≥ 1, got '1.5'"},
      {" --threads=300", "jelly run: --threads: expected a whole number from 1 to 256, got '300'"},
      {" other.toml", "jelly run: unexpected argument 'other.toml'"},
  };
  for (const auto& c : cases) {
    const Result r = jelly(run + c.args);
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << ":\n" << r.output;
    EXPECT_NE(r.output.find("(see jelly run --help)"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out())) << c.args;
  }
  const Result missing = jelly("check");
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.output.find("jelly check: SCENE is required"), std::string::npos)
      << missing.output;
  EXPECT_NE(missing.output.find("usage: jelly check SCENE"), std::string::npos) << missing.output;
  const Result help = jelly("params --help");
  EXPECT_EQ(help.code, 0);
  EXPECT_EQ(help.output.rfind("usage: jelly params SCENE", 0), 0u) << help.output;
}

TEST_F(Cli, MissingSceneFile) {
  const Result r = jelly("run " + (dir_ / "nope.toml").string() + " --out " + out());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("nope.toml"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out()));
}

TEST_F(Cli, ZeroLengthNormal) {
  const std::string p = (dir_ / "plane.toml").string();
  std::ofstream(p)
      << "[body]\ntype = \"cube\"\nn = 3\n[[terrain]]\nname = \"floor\"\ntype = \"plane\"\n"
         "point = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 0.0]\n";
  const Result r = jelly("run " + p + " --out " + out());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("normal"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out()));
}

TEST_F(Cli, BadSetValueIsRejectedBeforeAnythingRuns) {
  const Result r =
      jelly("run " + scene("course-2023.toml") + " --set springs.shear.ks=-1 --out " + out());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("springs.shear.ks"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out()));
}

TEST_F(Cli, UnstableRunStopsWithItsOwnExitCodeAndKeepsWhatItWrote) {
  if (std::string(JELLY_CLI_TASKS) != "solutions")
    GTEST_SKIP() << "needs the reference integrators";
  // The course's implicit Euler at h = 0.001 diverges after impact (contract §6).
  const Result r = jelly("run " + scene("course-2023.toml") +
                         " --integrator implicit_euler --every 100 --summary " + out());
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_NE(r.output.find("unstable"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Implicit Euler"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("h = 0.001"), std::string::npos) << r.output;
  std::ifstream sum(out());
  std::string line;
  long rows = -1;
  while (std::getline(sum, line)) ++rows;
  EXPECT_GT(rows, 10);  // frames before the detector fired are kept
}

TEST_F(Cli, CheckPrintsTheStableStepOfEveryIntegrator) {
  // The spring count and stable steps come from the tasks (the stubs build no springs): this runs
  // in a student release too, where it must not fail before the student has written anything.
  if (std::string(JELLY_CLI_TASKS) != "solutions") GTEST_SKIP() << "needs the reference springs";
  const Result r = jelly("check " + scene("course-2023.toml"));
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("12876 springs"), std::string::npos) << r.output;
  for (const char* k : {"explicit_euler", "implicit_euler", "rk4", "backward_euler"})
    EXPECT_NE(r.output.find(k), std::string::npos) << k;
}

TEST_F(Cli, ParamsListsDeclaredKeys) {
  const Result r = jelly("params " + scene("course-2023.toml"));
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* k :
       {"body.center", "springs.shear.ks", "terrain.floor.restitution", "simulation.dt"})
    EXPECT_NE(r.output.find(k), std::string::npos) << k;
}

// Every command takes a scene by name (under scenes/, with or without .toml) as well as by path
// (session::resolve_scene): the same run either way.
TEST_F(Cli, ASceneByNameIsTheSameSceneAsByPath) {
  const std::string base = " --duration 0.02 --every 10 --quiet --out ";
  const Result by_path =
      jelly("run " + scene("hard/n2.toml") + base + (dir_ / "path.csv").string());
  const Result by_name = jelly("run hard/n2" + base + (dir_ / "name.csv").string());
  ASSERT_EQ(by_path.code, 0) << by_path.output;
  ASSERT_EQ(by_name.code, 0) << by_name.output;
  const std::string a = file_text(dir_ / "path.csv");
  EXPECT_GT(a.size(), 100u);
  EXPECT_EQ(a, file_text(dir_ / "name.csv"));
  const Result params = jelly("params course-2023.toml");
  EXPECT_EQ(params.code, 0) << params.output;
  EXPECT_NE(params.output.find("scene.name"), std::string::npos) << params.output;
}

using jelly::test::column_of;

// Issue 28: `jelly probe`'s table lines up by display width (a task name with an en dash, three
// bytes, one column) and its name column is as wide as the longest name ("implicit Euler
// (predictor-corrector)" does not push its row out of line).
TEST_F(Cli, TheProbeTableLinesUpByDisplayWidth) {
  const Result r = jelly("probe");
  ASSERT_EQ(r.code, 0) << r.output;
  std::istringstream in(r.output);
  std::vector<std::size_t> columns;
  std::size_t rows = 0;
  const auto check_block = [&] {
    for (std::size_t c : columns) EXPECT_EQ(c, columns.front()) << r.output;
    columns.clear();
  };
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("student tasks of", 0) == 0) check_block();
    const std::size_t status =
        std::min(column_of(line, "looks implemented"), column_of(line, "NOT implemented yet"));
    if (line.rfind("  ", 0) == 0 && status != std::string::npos) {
      columns.push_back(status), ++rows;
      // A space between the name and the status, however long the name.
      const std::size_t byte =
          std::min(line.find("looks implemented"), line.find("NOT implemented"));
      EXPECT_EQ(line[byte - 1], ' ') << line;
    }
  }
  check_block();
  EXPECT_GE(rows, 10u) << r.output;
}

TEST_F(Cli, AnUnknownSceneSaysWhatWasTriedAndListsTheKnownNames) {
  const Result r = jelly("run no-such-scene --out " + out());
  EXPECT_EQ(r.code, 2);
  for (const char* part : {"no-such-scene: no such scene", "no-such-scene.toml",
                           "known scenes:", "course-2023", "hard/stiff-springs"})
    EXPECT_NE(r.output.find(part), std::string::npos) << part << " missing in:\n" << r.output;
  EXPECT_FALSE(fs::exists(out()));
}

}  // namespace
