// Tests of jelly-grade as a user runs it: the reference scores full marks, the stubs zero, hostile
// submissions fail their tests with a clear message while every other test still runs, results
// are reproducible, and the Gradescope / PrairieLearn / JUnit outputs have the documented shape.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <toml++/toml.h>
#include <nlohmann/json.hpp>

#include "shell_quote.hpp"

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

const fs::path kSource = JELLY_SOURCE_DIR;
const fs::path kWork = fs::path(JELLY_BINARY_DIR) / "tests-grader";
// An assignment's reference as a submission: every file of its `files`, from solutions/<id>/ or
// from a task module, in the folder the build makes (build/assignments/<id>/reference/).
fs::path reference_dir(const std::string& id) {
  return fs::path(JELLY_BINARY_DIR) / "assignments" / id / "reference";
}
// A1's hostile submissions (one folder each: the files laid over the reference).
const fs::path kHostile = kSource / "grader" / "tests" / "hostile" / "a1";

struct Cmd {
  int status = -1;
  std::string out;
};

Cmd run(const std::string& args) {
  const std::string cmd = jelly::testing::shell_quoted(JELLY_GRADE_EXE) + " " +
                          jelly::testing::quote_tree_paths(args) + " 2>&1";
  Cmd r;
  FILE* p = popen(cmd.c_str(), "r");
  char buf[4096];
  std::size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
  const int st = pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

Json read_json(const fs::path& p) {
  std::ifstream in(p);
  EXPECT_TRUE(in) << p;
  return Json::parse(in);
}

// A submission folder: the reference files, with the given hostile files laid over them.
fs::path submission(const std::string& name, const fs::path& overlay = {}) {
  const fs::path dir = kWork / "submissions" / name;
  fs::remove_all(dir);
  fs::create_directories(dir / "nested" / "src");
  for (const char* f :
       {"springs.cpp", "forces.cpp", "collision.cpp", "contact.cpp", "integrators.cpp"})
    fs::copy_file(reference_dir("a1") / f, dir / "nested" / "src" / f);
  if (!overlay.empty())
    for (const auto& e : fs::directory_iterator(overlay))
      fs::copy_file(e.path(), dir / "nested" / "src" / e.path().filename(),
                    fs::copy_options::overwrite_existing);
  std::ofstream(dir / "README.txt") << "not graded\n";
  return dir;
}

Json grade(const fs::path& sub, const std::string& name, const std::string& extra = "") {
  const fs::path out = kWork / "out" / name;
  fs::remove_all(out);
  const Cmd r = run("grade " + sub.string() + " --out " + out.string() +
                    " --format terminal,gradescope,prairielearn,junit,markdown,html " + extra);
  EXPECT_EQ(r.status, 0) << r.out;
  return read_json(out / "results.json");
}

const Json* find_test(const Json& results, const std::string& id) {
  for (const Json& t : results["tests"])
    if (t["name"].get<std::string>().find("[" + id + "]") != std::string::npos) return &t;
  return nullptr;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Whether `s` is valid UTF-8 (well-formed sequences only).
bool utf8_ok(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const unsigned c = static_cast<unsigned char>(s[i]);
    const std::size_t n = c < 0x80             ? 1
                          : (c & 0xE0) == 0xC0 ? 2
                          : (c & 0xF0) == 0xE0 ? 3
                          : (c & 0xF8) == 0xF0 ? 4
                                               : 0;
    if (n == 0 || i + n > s.size() || (n == 2 && c < 0xC2)) return false;
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return false;
    i += n;
  }
  return true;
}

// Task score from the Gradescope tests (tag 0 is the task id).
double task_score(const Json& results, const std::string& task) {
  double s = 0;
  for (const Json& t : results["tests"])
    if (t.contains("tags") && t["tags"][0] == task) s += t["score"].get<double>();
  return s;
}

void check_gradescope_schema(const Json& j) {
  ASSERT_TRUE(j.is_object());
  ASSERT_TRUE(j["score"].is_number());
  ASSERT_TRUE(j["execution_time"].is_number());
  ASSERT_TRUE(j["tests"].is_array());
  const std::set<std::string> vis = {"hidden", "after_due_date", "after_published", "visible"};
  for (const Json& t : j["tests"]) {
    ASSERT_TRUE(t["name"].is_string());
    ASSERT_TRUE(t["output"].is_string());
    ASSERT_TRUE(t["status"] == "passed" || t["status"] == "failed") << t.dump();
    ASSERT_TRUE(vis.count(t["visibility"].get<std::string>()));
    if (t.contains("score")) {
      ASSERT_TRUE(t["score"].is_number());
      ASSERT_TRUE(t["max_score"].is_number());
      EXPECT_LE(t["score"].get<double>(), t["max_score"].get<double>() + 1e-9);
    }
  }
}

void check_prairielearn_schema(const Json& j) {
  ASSERT_TRUE(j["gradable"].is_boolean());
  ASSERT_TRUE(j["score"].is_number());
  EXPECT_GE(j["score"].get<double>(), 0.0);
  EXPECT_LE(j["score"].get<double>(), 1.0);
  ASSERT_TRUE(j["tests"].is_array());
  for (const Json& t : j["tests"]) {
    ASSERT_TRUE(t["name"].is_string());
    ASSERT_TRUE(t["points"].is_number());
    ASSERT_TRUE(t["max_points"].is_number());
  }
  ASSERT_TRUE(j["images"].is_array());
  for (const Json& i : j["images"]) {
    ASSERT_TRUE(i["label"].is_string());
    ASSERT_EQ(i["url"].get<std::string>().rfind("data:image/", 0), 0u);
  }
}

}  // namespace

// Each command takes only its own options; a bad one is named with what it expects (exit code 2,
// before anything is built); --help prints the usage with exit code 0.
TEST(Grader, BadCommandLinesNameTheOptionAndExitTwo) {
  const struct {
    const char* args;
    const char* message;
  } cases[] = {
      {"grade x --format terminal,pdf",
       "jelly-grade grade: --format: expected one of terminal, gradescope, "
       "prairielearn, junit, markdown, html, got 'pdf'"},
      {"grade x --table t.md", "jelly-grade grade: unknown option --table"},
      {"grade x --timeout 0", "jelly-grade grade: --timeout: expected a number > 0, got '0'"},
      {"grade x --compile-memory 10",
       "jelly-grade grade: --compile-memory: expected a number ≥ 64, got '10'"},
      {"grade x --jobs", "jelly-grade grade: --jobs needs a value (N)"},
      {"grade", "jelly-grade grade: SUBMISSION_DIR is required"},
      {"batch in", "jelly-grade batch: --out is required"},
      {"regrade x", "jelly-grade: unknown command regrade"},
  };
  for (const auto& c : cases) {
    const Cmd r = run(c.args);
    EXPECT_EQ(r.status, 2) << c.args;
    EXPECT_NE(r.out.find(c.message), std::string::npos) << c.args << ":\n" << r.out;
    EXPECT_NE(r.out.find("usage:"), std::string::npos) << r.out;
  }
  const Cmd help = run("--help");
  EXPECT_EQ(help.status, 0);
  EXPECT_EQ(help.out.rfind("usage:", 0), 0u) << help.out;
}

// --help lists each option under a command that takes it: for every option of every command's
// lines, that command (given its required arguments) does not call it unknown. A sentinel unknown
// option after it makes every command stop at the command line, before it runs.
TEST(Grader, HelpListsEachOptionUnderACommandThatTakesIt) {
  const std::map<std::string, std::string> required{{"grade", "x"},
                                                    {"batch", "x --out y"},
                                                    {"merge", "x --out y"},
                                                    {"similarity", "x --out y"},
                                                    {"gradescope-zip", "x.zip"}};
  const Cmd help = run("--help");
  ASSERT_EQ(help.status, 0);
  std::istringstream lines(help.out);
  std::string line, command;
  std::map<std::string, std::set<std::string>> listed;
  while (std::getline(lines, line)) {
    if (line.rfind("  jelly-grade ", 0) == 0)
      command = line.substr(14, line.find(' ', 14) - 14);
    else if (line.rfind("      ", 0) != 0)
      command.clear();  // "common options", "sandbox", "exit status": several commands
    if (command.empty()) continue;
    for (auto at = line.find("--"); at != std::string::npos; at = line.find("--", at + 2)) {
      const auto end = line.find_first_not_of("abcdefghijklmnopqrstuvwxyz-", at + 2);
      listed[command].insert(line.substr(at, end - at));
    }
  }
  EXPECT_EQ(listed["merge"].count("--similarity"), 0u) << "merge takes no --similarity";
  EXPECT_EQ(listed["batch"].count("--similarity"), 1u) << help.out;
  EXPECT_GE(listed.size(), 7u) << help.out;  // the commands that take options
  for (const auto& [cmd, options] : listed)
    for (const std::string& option : options) {
      const auto req = required.find(cmd);
      const Cmd r = run(cmd + " " + (req == required.end() ? "" : req->second) + " " + option +
                        " --zz-sentinel");
      EXPECT_EQ(r.status, 2) << cmd << " " << option << ": " << r.out;
      EXPECT_EQ(r.out.find("unknown option " + option + "\n"), std::string::npos)
          << "--help lists " << option << " under " << cmd << ", which does not take it";
    }
}

TEST(Grader, ReferenceScoresFullMarksAndOutputsHaveTheirSchemas) {
  const Json r = grade(submission("reference"), "reference");
  EXPECT_DOUBLE_EQ(r["score"].get<double>(), 80.0);
  for (const Json& t : r["tests"])
    EXPECT_EQ(t["status"], "passed") << t["name"] << "\n" << t["output"];
  check_gradescope_schema(r);
  const fs::path out = kWork / "out" / "reference";
  check_prairielearn_schema(read_json(out / "prairielearn.json"));
  EXPECT_EQ(read_json(out / "prairielearn.json")["score"].get<double>(), 1.0);
  std::ifstream junit(out / "junit.xml");
  std::stringstream x;
  x << junit.rdbuf();
  EXPECT_NE(x.str().find("<testsuites"), std::string::npos);
  EXPECT_EQ(x.str().find("<failure"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "report.md"));
  EXPECT_TRUE(fs::exists(out / "com-height.svg"));
  EXPECT_TRUE(fs::exists(out / "report.html"));
}

TEST(Grader, StubsScoreZeroWithoutCrashing) {
  const Json r = grade(kSource / "assignments" / "a1", "stubs");
  EXPECT_EQ(r["score"].get<double>(), 0.0);
  check_gradescope_schema(r);
  for (const Json& t : r["tests"]) {
    const std::string o = t["output"];
    EXPECT_EQ(o.find("crashed"), std::string::npos) << t["name"] << o;
    EXPECT_EQ(o.find("took longer"), std::string::npos) << t["name"] << o;
  }
}

TEST(Grader, TwoRunsGiveIdenticalResults) {
  const fs::path sub = submission("determinism");
  Json a = grade(sub, "det-a"), b = grade(sub, "det-b");
  a.erase("execution_time");
  b.erase("execution_time");
  EXPECT_EQ(a.dump(), b.dump());
}

TEST(Grader, PublicVisibilityRunsOnlyPublicTests) {
  const Json r = grade(submission("public"), "public", "--visibility public");
  EXPECT_GT(r["score"].get<double>(), 0.0);
  EXPECT_LT(r["score"].get<double>(), 80.0 + 1e-9);
  for (const Json& t : r["tests"]) EXPECT_EQ(t["visibility"], "visible") << t["name"];
  EXPECT_EQ(find_test(r, "a1.t4.spring_force.random"), nullptr);
}

struct Hostile {
  const char* name;
  const char* case_id;  // a test of the attacked task
  const char* message;  // what its output must say
  const char*
      file_tasks;  // the tasks of the attacked file ("A1.T1 A1.T2 "): only these may lose points
};

class HostileSubmission : public ::testing::TestWithParam<Hostile> {};

TEST_P(HostileSubmission, FailsItsTestsWithAClearMessageAndTheRestStillRun) {
  const Hostile h = GetParam();
  fs::remove("/tmp/jelly-grade-hostile-was-here");
  const Json r = grade(submission(h.name, kHostile / h.name), h.name, "--timeout 3");
  check_gradescope_schema(r);
  const Json* t = find_test(r, h.case_id);
  ASSERT_NE(t, nullptr) << r.dump(1);
  EXPECT_EQ((*t)["status"], "failed");
  EXPECT_NE((*t)["output"].get<std::string>().find(h.message), std::string::npos) << (*t)["output"];
  // The other files' tasks still ran and kept their points.
  for (const char* task : {"A1.T1", "A1.T4", "A1.T6", "A1.T8", "A1.T13"}) {
    if (std::string(h.file_tasks).find(std::string(task) + " ") != std::string::npos) continue;
    EXPECT_GT(task_score(r, task), 0.0) << task << " lost its points in " << h.name;
  }
  EXPECT_FALSE(fs::exists("/tmp/jelly-grade-hostile-was-here"));
}

INSTANTIATE_TEST_SUITE_P(
    Grader, HostileSubmission,
    ::testing::Values(
        Hostile{"segfault", "a1.t4.spring_force.values", "crashed with SIGSEGV", "A1.T4 A1.T5 "},
        Hostile{"infinite_loop", "a1.t13.rk4.free_fall", "took longer than 3 s",
                "A1.T10 A1.T11 A1.T12 A1.T13 "},
        Hostile{"exit_in_function", "a1.t6.collide_plane.eps", "exit() called?", "A1.T6 A1.T7 "},
        Hostile{"huge_output", "a1.t1.structural.n3", "printed more than 64 MiB",
                "A1.T1 A1.T2 A1.T3 "},
        Hostile{"read_reference", "a1.t8.contact_plane.eps", "tried to open a file",
                "A1.T8 A1.T9 "},
        Hostile{"write_outside", "a1.t2.shear.n3", "tried to open a file", "A1.T1 A1.T2 A1.T3 "}),
    [](const ::testing::TestParamInfo<Hostile>& i) { return std::string(i.param.name); });

// Task scores of the reference, for "every other task keeps its points".
// Each test process grades its own copy: CTest runs these tests in separate processes at the same
// time, and one shared folder was emptied by one while the other graded it.
const Json& reference_results() {
  static const std::string name = "reference-for-costs-" + std::to_string(getpid());
  static const Json r = grade(submission(name), name);
  return r;
}

const char* const kAllTasks[] = {"A1.T1", "A1.T2", "A1.T3",  "A1.T4",  "A1.T5",  "A1.T6", "A1.T7",
                                 "A1.T8", "A1.T9", "A1.T10", "A1.T11", "A1.T12", "A1.T13"};

TEST(Grader, SubmissionThatDoesNotCompileGetsTheErrorsAndLosesOnlyThatFilesTasks) {
  const Json r = grade(submission("no_compile", kHostile / "no_compile"), "no_compile");
  const Json& compile = r["tests"][0];
  EXPECT_EQ(compile["status"], "failed");
  const std::string o = compile["output"];
  EXPECT_NE(o.find("nested/src/integrators.cpp:"), std::string::npos)
      << o;  // path as in the submission
  EXPECT_NE(o.find("error"), std::string::npos) << o;
  EXPECT_NE(o.find("integrators.cpp did not compile: its tasks A1.T10, A1.T11, A1.T12, A1.T13"),
            std::string::npos)
      << o;
  for (const char* task : kAllTasks) {
    const bool mine = std::string(task) >= "A1.T10" && std::string(task).size() == 6;
    EXPECT_NEAR(task_score(r, task), mine ? 0.0 : task_score(reference_results(), task), 1e-6)
        << task;
  }
}

// One missing ';' in forces.cpp: its tasks score 0 with the compiler's message, every other task
// keeps full points (graded with the stub of forces.cpp in its place), and every report names the
// file and what it cost.
TEST(Grader, MissingSemicolonInForcesCostsOnlyTheForcesTasks) {
  const fs::path dir = submission("missing_semicolon");
  const fs::path forces = dir / "nested" / "src" / "forces.cpp";
  std::string text;
  {
    std::ifstream in(forces, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    text = s.str();
  }
  const auto semi = text.find(";\n", text.find("return "));
  ASSERT_NE(semi, std::string::npos);
  text.erase(semi, 1);
  std::ofstream(forces, std::ios::binary) << text;
  const Json r = grade(dir, "missing_semicolon");
  const fs::path out = kWork / "out" / "missing_semicolon";
  double forces_max = 0;
  for (const Json& t : r["tests"])
    if (t.contains("tags") && (t["tags"][0] == "A1.T4" || t["tags"][0] == "A1.T5")) {
      forces_max += t["max_score"].get<double>();
      EXPECT_EQ(t["status"], "failed");
      const std::string o = t["output"];
      EXPECT_NE(o.find("not run: forces.cpp did not compile"), std::string::npos) << o;
      EXPECT_NE(o.find("nested/src/forces.cpp:"), std::string::npos)
          << "the compiler's message: " << o;
    }
  EXPECT_NEAR(forces_max, 20.0, 1e-4);  // shares rounded to 1e-6 each
  for (const char* task : kAllTasks) {
    const bool mine = std::string(task) == "A1.T4" || std::string(task) == "A1.T5";
    EXPECT_NEAR(task_score(r, task), mine ? 0.0 : task_score(reference_results(), task), 1e-6)
        << task;
  }
  EXPECT_NEAR(r["score"].get<double>(), 60.0, 1e-6);
  const std::string headline = "forces.cpp did not compile: its tasks A1.T4, A1.T5 (20.00 points)";
  EXPECT_NE(r["tests"][0]["output"].get<std::string>().find(headline), std::string::npos)
      << r["tests"][0]["output"];
  EXPECT_NE(r["tests"][0]["output"].get<std::string>().find("expected"), std::string::npos);
  const std::string md = read_text(out / "report.md"), html = read_text(out / "report.html");
  EXPECT_NE(md.find("## forces.cpp did not compile"), std::string::npos) << md.substr(0, 2000);
  EXPECT_NE(md.find("A1.T4, A1.T5 (20.00 points)"), std::string::npos) << md.substr(0, 2000);
  EXPECT_NE(html.find("<h2>forces.cpp did not compile</h2>"), std::string::npos);
  EXPECT_NE(html.find(headline), std::string::npos);
  const Cmd term = run("grade " + dir.string() + " --out " + (out / "again").string() +
                       " --format terminal --no-frames");
  EXPECT_NE(term.out.find(headline), std::string::npos) << term.out;
  EXPECT_NE(term.out.find("Total: 60.00 / 80.00"), std::string::npos) << term.out;
}

// forces.cpp uses a non-static helper that springs.cpp defines, and springs.cpp does not compile:
// the five files cannot link together, so each usable file is linked alone with the other stubs;
// forces.cpp then lacks the helper (its tasks 0, with the linker's message), the other files keep
// their points, and the course scene (which needs all of them) is not run.
TEST(Grader, FilesThatDoNotLinkTogetherAreEachGradedWithTheOtherStubs) {
  const fs::path dir = submission("shared_helper");
  const fs::path src = dir / "nested" / "src";
  const std::string ns = "namespace jelly::a1 {\n";
  std::string springs = read_text(src / "springs.cpp"), forces = read_text(src / "forces.cpp");
  ASSERT_NE(springs.find(ns), std::string::npos);
  ASSERT_NE(forces.find(ns), std::string::npos);
  springs.insert(springs.find(ns) + ns.size(),
                 "double jelly_shared_scale();\ndouble jelly_shared_scale() { return 1.0; }\n"
                 "int jelly_broken = ;\n");
  forces.insert(forces.find(ns) + ns.size(), "double jelly_shared_scale();\n");
  const std::string ret = "return (-ks * (length - rest_length)) * u;";
  ASSERT_NE(forces.find(ret), std::string::npos)
      << "the reference forces.cpp (solutions/tasks/mass_spring/) changed: update this test";
  forces.replace(forces.find(ret), ret.size(),
                 "return (-ks * jelly_shared_scale() * (length - rest_length)) * u;");
  std::ofstream(src / "springs.cpp", std::ios::binary) << springs;
  std::ofstream(src / "forces.cpp", std::ios::binary) << forces;
  const Json r = grade(dir, "shared_helper");
  for (const char* task : kAllTasks) {
    const std::string t = task;
    const bool lost = t == "A1.T1" || t == "A1.T2" || t == "A1.T3" || t == "A1.T4" || t == "A1.T5";
    EXPECT_NEAR(task_score(r, task), lost ? 0.0 : task_score(reference_results(), task), 1e-6)
        << task;
  }
  const std::string o = r["tests"][0]["output"];
  EXPECT_NE(o.find("springs.cpp did not compile: its tasks A1.T1, A1.T2, A1.T3"), std::string::npos)
      << o;
  EXPECT_NE(o.find("forces.cpp did not link: its tasks A1.T4, A1.T5"), std::string::npos) << o;
  EXPECT_NE(o.find("undefined reference to `jelly::a1::jelly_shared_scale()'"), std::string::npos)
      << o;
  const Json* t4 = find_test(r, "a1.t4.spring_force.values");
  ASSERT_NE(t4, nullptr);
  EXPECT_NE((*t4)["output"].get<std::string>().find("not run: forces.cpp did not link"),
            std::string::npos)
      << (*t4)["output"];
  const Json* course = find_test(r, "a1.course.scene");
  ASSERT_NE(course, nullptr);
  EXPECT_NE((*course)["output"].get<std::string>().find("they do not link together"),
            std::string::npos)
      << (*course)["output"];
}

// A correct submission that prints 100 KB of mixed-script UTF-8 (Chinese, arrows, degree signs,
// emoji), invalid bytes, NUL, terminal escapes and markup: full marks, and the reports show the
// text as valid UTF-8, escaped for their format.
TEST(Grader, PrintingAnyBytesKeepsFullMarksAndTheReportsShowTheTextSafely) {
  const fs::path dir = submission("utf8_printer");
  const fs::path springs = dir / "nested" / "src" / "springs.cpp";
  std::string text = read_text(springs);
  const std::string sig =
      "void add_structural_springs(const CubeLattice& cube, std::vector<Spring>& out) {\n";
  const auto at = text.find(sig);
  ASSERT_NE(at, std::string::npos) << "solutions/a1/springs.cpp changed: update this test";
  text.insert(at + sig.size(),
              "  static bool printed = false;\n"
              "  if (!printed) {\n"
              "    printed = true;\n"
              "    std::fputs(\"jelly-utf8 \\xff\\xfe bad \\xe6\\xb8 cut \\x1b[2J\\x1b[31m "
              "<script>alert(1)</script> "
              "**not bold** NUL[\", stdout);\n"
              "    std::fputc(0, stdout);\n"
              "    std::fputs(\"]\\n\", stdout);\n"
              "    for (int k = 0; k < 3000; ++k)  // about 100 KB\n"
              "      std::fputs(\"\\xe6\\xb8\\xa9\\xe5\\xba\\xa6 \\xe2\\x86\\x92 20 \\xc2\\xb0\" "
              "\"C \\xf0\\x9f\\x8c\\xa1 "
              "\\xe5\\xbc\\xb9\\xe7\\xb0\\xa7 \\xe2\\x86\\x90\\n\", stdout);\n"
              "  }\n");
  text = "#include <cstdio>\n" + text;
  std::ofstream(springs, std::ios::binary) << text;
  const Json r = grade(dir, "utf8_printer");
  double max = 0;
  for (const Json& t : r["tests"])
    if (t.contains("max_score")) max += t["max_score"].get<double>();
  EXPECT_NEAR(r["score"].get<double>(), max, 1e-6);
  EXPECT_NEAR(r["score"].get<double>(), 80.0, 1e-6);
  const fs::path out = kWork / "out" / "utf8_printer";
  const std::string line =
      "\xe6\xb8\xa9\xe5\xba\xa6 \xe2\x86\x92 20 \xc2\xb0"
      "C \xf0\x9f\x8c\xa1";
  const std::string results = read_text(out / "results.json"), md = read_text(out / "report.md"),
                    html = read_text(out / "report.html");
  for (const std::string* f : {&results, &md, &html}) {
    EXPECT_TRUE(utf8_ok(*f));
    EXPECT_EQ(f->find('\x1b'), std::string::npos);
    EXPECT_EQ(f->find('\0'), std::string::npos);
    EXPECT_EQ(f->find("\xe6\xb8 cut"), std::string::npos) << "an invalid byte left as it was";
  }
  const Json* t = find_test(r, "a1.t1.structural.n3");
  ASSERT_NE(t, nullptr);
  const std::string o = (*t)["output"];
  EXPECT_NE(o.find("jelly-utf8 \xef\xbf\xbd\xef\xbf\xbd bad \xef\xbf\xbd cut \xe2\x90\x9b[2J"),
            std::string::npos)
      << o;
  EXPECT_NE(o.find("NUL[\xe2\x90\x80]"), std::string::npos) << o;
  EXPECT_NE(o.find(line), std::string::npos) << o;
  EXPECT_NE(md.find(line), std::string::npos);
  EXPECT_NE(md.find("jelly-utf8"), std::string::npos);
  EXPECT_NE(html.find(line), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
  EXPECT_EQ(html.find("<script>"), std::string::npos) << "markup of the student in the page";
}

TEST(Grader, IncludingTheHiddenDataIsRefusedBeforeCompiling) {
  const Json r = grade(submission("include_hidden", kHostile / "include_hidden"), "include_hidden");
  // Refused before compiling: forces.cpp's tasks only (its stub stands in for it).
  EXPECT_EQ(task_score(r, "A1.T4") + task_score(r, "A1.T5"), 0.0);
  EXPECT_NEAR(task_score(r, "A1.T1"), task_score(reference_results(), "A1.T1"), 1e-6);
  const std::string o = r["tests"][0]["output"];
  EXPECT_NE(o.find("is not allowed in a graded file"), std::string::npos) << o;
  EXPECT_EQ(o.find("format_version"), std::string::npos) << "hidden data leaked: " << o;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A report's frames table in OUT/report.md: six rows, the student's and the reference's picture
// in each (PNG files beside the report), `last_row` the last.
void expect_six_frames_each_side(const fs::path& out, const std::string& last_row) {
  const std::string md = read_text(out / "report.md");
  ASSERT_NE(md.find("| t [s] | yours | reference |"), std::string::npos) << md;
  EXPECT_EQ(md.find("Frames not available"), std::string::npos) << md;
  EXPECT_EQ(count(md, "](frames/yours/frame_"), 6u) << md;
  EXPECT_EQ(count(md, "](frames/reference/frame_"), 6u) << md;
  EXPECT_NE(md.find(last_row), std::string::npos) << md;
  for (const char* side : {"yours", "reference"})
    for (int k = 0; k < 6; ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%05d.png", k);
      const std::string png = read_text(out / "frames" / side / name);
      ASSERT_GT(png.size(), 1000u) << side << "/" << name;
      EXPECT_EQ(png.substr(1, 3), "PNG") << side << "/" << name;
    }
}

// The course scene's frames: recorded in the sandbox, never graded, never reference data.
TEST(GraderFrames, RecordedFramesAreNeitherGradedNorReferenceData) {
  const Json ref = read_json(kSource / "assignments" / "a1" / "grader" / "data" / "public" /
                             "a1.course.scene.json");
  ASSERT_TRUE(ref["params"].contains("frame_times")) << "the case records no frames";
  ASSERT_TRUE(ref["outputs"].contains("com_y"));
  for (const auto& [name, value] : ref["outputs"].items())
    EXPECT_NE(name.rfind("frame_", 0), 0u) << name << " stored as reference data";
  const Json r = grade(submission("frames-ref"), "frames-ref", "--no-frames");
  EXPECT_EQ(r.dump().find("frame_"), std::string::npos) << "frames in results.json";
  const std::string md = read_text(kWork / "out" / "frames-ref" / "report.md");
  EXPECT_EQ(md.find("Frames"), std::string::npos) << "--no-frames still made a frames section";
}

TEST(GraderFrames, ReportShowsYourFramesBesideTheReferences) {
#if !JELLY_GRADE_HAS_RENDER
  GTEST_SKIP()
      << "built without the viewer: the report has no frames (covered by WithoutARenderer...)";
#endif
  const Json r = grade(submission("frames"), "frames");
  EXPECT_DOUBLE_EQ(r["score"].get<double>(), 80.0);
  const fs::path out = kWork / "out" / "frames";
  // One row per frame time of assignments/a1/grader/cases/course.toml (0.5, 1, 2, 3, 5, 10 s), both
  // sides.
  expect_six_frames_each_side(out,
                              "| 10.00 | ![yours at t = 10.00 s](frames/yours/frame_00005.png)");
  // The HTML report is self-contained: the twelve pictures inline.
  const std::string html = read_text(out / "report.html");
  EXPECT_EQ(count(html, "src=\"data:image/png;base64,"), 12u);
  EXPECT_NE(html.find("<th>yours</th><th>reference</th>"), std::string::npos);
}

// A2's frames: cloth-2024 (the manifest's default scene) at the times of its course case, the
// driven sphere drawn where the run had it; the recorded outputs are not reference data either.
TEST(GraderFrames, A2ReportShowsTheClothFramesBesideTheReferences) {
  const Json ref = read_json(kSource / "assignments" / "a2" / "grader" / "data" / "public" /
                             "a2.course.cloth2024.json");
  ASSERT_TRUE(ref["params"].contains("frame_times")) << "the case records no frames";
  for (const auto& [name, value] : ref["outputs"].items())
    EXPECT_NE(name.rfind("frame_", 0), 0u) << name << " stored as reference data";
#if !JELLY_GRADE_HAS_RENDER
  GTEST_SKIP() << "built without the viewer: the report has no frames";
#endif
  const Json r = grade(reference_dir("a2"), "frames-a2", "--assignment a2");
  EXPECT_DOUBLE_EQ(r["score"].get<double>(), 85.0) << "80 and the bonus's 5";
  EXPECT_EQ(r.dump().find("frame_"), std::string::npos) << "frames in results.json";
  // assignments/a2/grader/cases/course.toml: 0.25, 0.5, 0.75, 1, 1.25 and 1.6 s, both sides.
  expect_six_frames_each_side(kWork / "out" / "frames-a2",
                              "| 1.60 | ![yours at t = 1.60 s](frames/yours/frame_00005.png)");
}

TEST(GraderFrames, WithoutARendererTheReportSaysWhyAndGradingIsUnchanged) {
  const fs::path sub = submission("frames-none");
  const Json with = grade(sub, "frames-default", "--no-frames");
  setenv("JELLY_GRADE_JELLY", "/no/such/jelly", 1);
  const Json missing = grade(sub, "frames-missing");
  setenv("JELLY_GRADE_JELLY", "/bin/false", 1);  // a renderer that fails
  const Json failing = grade(sub, "frames-failing");
  unsetenv("JELLY_GRADE_JELLY");
  Json a = with, b = missing, c = failing;
  for (Json* j : {&a, &b, &c}) j->erase("execution_time");
  EXPECT_EQ(a.dump(), b.dump());
  EXPECT_EQ(a.dump(), c.dump());
  const std::string md_missing = read_text(kWork / "out" / "frames-missing" / "report.md");
  EXPECT_NE(md_missing.find("Frames not available: /no/such/jelly is missing"), std::string::npos)
      << md_missing;
  const std::string md_failing = read_text(kWork / "out" / "frames-failing" / "report.md");
  // The note may quote the renderer's own words, so report.md escapes it as student text.
  EXPECT_NE(md_failing.find("Frames not available: \\`jelly render --replay\\` failed (exit 1)"),
            std::string::npos)
      << md_failing;
  const std::string html = read_text(kWork / "out" / "frames-failing" / "report.html");
  EXPECT_NE(html.find("<p>Frames not available: "), std::string::npos);
}

TEST(Grader, BatchGradesEveryFolderAndWritesScoresCsv) {
  const fs::path dir = kWork / "batch";
  fs::remove_all(dir);
  fs::create_directories(dir / "in");
  fs::copy(submission("batch-ref"), dir / "in" / "alice", fs::copy_options::recursive);
  fs::copy(kSource / "assignments" / "a1", dir / "in" / "bob", fs::copy_options::recursive);
  // carol's files as a Canvas bulk download names them, forces.cpp resubmitted (-1: the later);
  // dave handed in no task file.
  const std::vector<std::string> files = {"springs.cpp", "forces.cpp", "collision.cpp",
                                          "contact.cpp", "integrators.cpp"};
  fs::create_directories(dir / "in" / "carol");
  for (const std::string& f : files)
    fs::copy_file(reference_dir("a1") / f, dir / "in" / "carol" / ("carol_123_456_" + f));
  fs::copy_file(kSource / "assignments" / "a1" / "forces.cpp",
                dir / "in" / "carol" / "carol_123_456_forces.cpp",
                fs::copy_options::overwrite_existing);
  fs::copy_file(reference_dir("a1") / "forces.cpp",
                dir / "in" / "carol" / "carol_123_456_forces-1.cpp");
  // A resubmission number too long for any integer is not an LMS name: no grader error.
  std::ofstream(dir / "in" / "carol" / "carol_123_456_forces-99999999999999999999.cpp") << "x\n";
  // ... and contact.cpp as Moodle names a file it downloads without folders.
  fs::rename(dir / "in" / "carol" / "carol_123_456_contact.cpp",
             dir / "in" / "carol" / "Carol Smith_123_assignsubmission_file_contact.cpp");
  fs::create_directories(dir / "in" / "dave");
  std::ofstream(dir / "in" / "dave" / "notes.txt") << "I ran out of time\n";
  const Cmd r = run("batch " + (dir / "in").string() + " --assignment a1 --out " +
                    (dir / "out").string() + " --jobs 2");
  ASSERT_EQ(r.status, 0) << r.out;
  std::ifstream csv(dir / "out" / "scores.csv");
  std::string header, alice, bob, carol, dave;
  std::getline(csv, header);
  std::getline(csv, alice);
  std::getline(csv, bob);
  std::getline(csv, carol);
  std::getline(csv, dave);
  for (std::string* row : {&header, &alice, &bob, &carol, &dave})
    if (!row->empty() && row->back() == '\r') row->pop_back();  // RFC 4180 line ends
  // For an LMS import: the id, the points, the percentage, an empty column for the hand-graded
  // report, then each task; no column for the course scene (0 points, not a bonus).
  EXPECT_EQ(header.rfind("student,points,max_points,percent,total,hand_graded,hand_graded_max,"
                         "compiled,A1.T1,",
                         0),
            0u)
      << header;
  EXPECT_NE(header.find(",A1.T13,name,email,missing_files,error"), std::string::npos) << header;
  EXPECT_EQ(header.find("A1.COURSE"), std::string::npos) << header;
  EXPECT_EQ(alice.rfind("alice,80.00,80.00,100.00,80.00,,20.00,1,5.00,", 0), 0u) << alice;
  EXPECT_EQ(bob.rfind("bob,0.00,80.00,0.00,0.00,,20.00,1,0.00,", 0), 0u) << bob;
  EXPECT_EQ(bob.substr(bob.size() - 4), ",,,,") << "no name, no email, no missing file: " << bob;
  EXPECT_EQ(carol.rfind("carol,80.00,80.00,100.00,80.00,,20.00,1", 0), 0u) << carol;
  EXPECT_EQ(dave.rfind("dave,0.00,80.00,0.00,0.00,,20.00,1", 0), 0u) << dave;
  for (const std::string* row : {&alice, &bob, &carol, &dave})
    EXPECT_EQ(std::count(row->begin(), row->end(), ','),
              std::count(header.begin(), header.end(), ','))
        << *row;
  EXPECT_NE(dave.find(",springs.cpp forces.cpp collision.cpp contact.cpp integrators.cpp,"),
            std::string::npos)
      << dave;
  const std::string said =
      read_json(dir / "out" / "students" / "carol" / "results.json")["output"].get<std::string>();
  EXPECT_NE(said.find("Note: carol_123_456_forces-1.cpp was graded as forces.cpp (a "
                      "learning-management system's bulk-download name)"),
            std::string::npos)
      << said;
  EXPECT_NE(said.find("Note: Carol Smith_123_assignsubmission_file_contact.cpp was graded as "
                      "contact.cpp"),
            std::string::npos)
      << said;
  for (const char* report : {"results.json", "report.md", "report.html"})
    EXPECT_TRUE(fs::exists(dir / "out" / "students" / "alice" / report)) << report;
  // Not a terminal: one progress line per submission.
  for (const char* who : {"alice", "bob", "carol", "dave"})
    EXPECT_NE(r.out.find("] " + std::string(who) + ": "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find('\r'), std::string::npos) << "carriage returns in a log";
}

namespace {

// A zip with the given entries stored as they are (names unchecked: a hostile export), each a file
// or, with `link`, a symlink whose target is `data`.
struct ZipEntry {
  std::string name, data;
  bool link = false;
};

void write_zip(const fs::path& file, const std::vector<ZipEntry>& entries) {
  const auto crc32 = [](const std::string& d) {
    std::uint32_t c = 0xFFFFFFFFu;
    for (unsigned char b : d) {
      c ^= b;
      for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return c ^ 0xFFFFFFFFu;
  };
  std::string out, central;
  const auto u16 = [](std::string& s, unsigned v) {
    s += static_cast<char>(v & 0xFF);
    s += static_cast<char>((v >> 8) & 0xFF);
  };
  const auto u32 = [&](std::string& s, std::uint32_t v) {
    u16(s, v & 0xFFFF);
    u16(s, v >> 16);
  };
  for (const ZipEntry& e : entries) {
    const std::uint32_t offset = static_cast<std::uint32_t>(out.size());
    const std::uint32_t crc = crc32(e.data);
    const auto size = static_cast<std::uint32_t>(e.data.size());
    u32(out, 0x04034b50);  // local file header
    u16(out, 20);
    u16(out, 0);
    u16(out, 0);  // stored
    u16(out, 0);
    u16(out, 0x21);
    u32(out, crc);
    u32(out, size);
    u32(out, size);
    u16(out, static_cast<unsigned>(e.name.size()));
    u16(out, 0);
    out += e.name + e.data;
    u32(central, 0x02014b50);
    u16(central, 0x0314);  // made by Unix, so that the mode (and a symlink) counts
    u16(central, 20);
    u16(central, 0);
    u16(central, 0);
    u16(central, 0);
    u16(central, 0x21);
    u32(central, crc);
    u32(central, size);
    u32(central, size);
    u16(central, static_cast<unsigned>(e.name.size()));
    u16(central, 0);
    u16(central, 0);
    u16(central, 0);
    u16(central, 0);
    u32(central, (e.link ? 0120777u : 0100644u) << 16);
    u32(central, offset);
    central += e.name;
  }
  const auto at = static_cast<std::uint32_t>(out.size());
  out += central;
  u32(out, 0x06054b50);
  u16(out, 0);
  u16(out, 0);
  u16(out, static_cast<unsigned>(entries.size()));
  u16(out, static_cast<unsigned>(entries.size()));
  u32(out, static_cast<std::uint32_t>(central.size()));
  u32(out, at);
  u16(out, 0);
  std::ofstream(file, std::ios::binary) << out;
}

// scores.csv's rows by student id (RFC 4180 fields; the tests' fields hold no line break).
std::map<std::string, std::vector<std::string>> csv_rows(const fs::path& file) {
  std::map<std::string, std::vector<std::string>> rows;
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::vector<std::string> f(1);
    bool quoted = false;
    for (std::size_t k = 0; k < line.size(); ++k) {
      const char c = line[k];
      if (quoted && c == '"' && k + 1 < line.size() && line[k + 1] == '"') {
        f.back() += '"';
        ++k;
      } else if (c == '"') {
        quoted = !quoted;
      } else if (c == ',' && !quoted) {
        f.emplace_back();
      } else {
        f.back() += c;
      }
    }
    rows[f[0]] = f;
  }
  return rows;
}

std::string record_text(const fs::path& out, const std::string& id) {
  return read_text(out / "students" / id / "record.json");
}

const std::vector<std::string> kTaskFiles = {"springs.cpp", "forces.cpp", "collision.cpp",
                                             "contact.cpp", "integrators.cpp"};

}  // namespace

// Every bad entry of a class folder gets a row saying what is wrong, and the rest is graded:
// a file, an empty folder (or one with only .git), a folder that is a symlink out of the class,
// two folders whose ids differ only in case, an id unsafe as a folder name; a symlink out of a
// submission is not followed (a note says so) and the rest of that submission is graded.
TEST(Grader, BatchBadInputsEachGetARowSayingWhyAndTheRestIsGraded) {
  const fs::path dir = kWork / "batch-bad";
  fs::remove_all(dir);
  const fs::path in = dir / "in";
  fs::create_directories(in);
  fs::copy(submission("batch-bad-ref"), in / "alice", fs::copy_options::recursive);
  std::ofstream(in / "notes.txt") << "not a submission\n";
  fs::create_directories(in / "empty");
  fs::create_directories(in / "only-git" / ".git");
  std::ofstream(in / "only-git" / ".git" / "HEAD") << "ref: refs/heads/main\n";
  fs::create_directories(in / "linker");
  std::ofstream(in / "linker" / "springs.cpp") << "// mine\n";
  fs::create_symlink("/etc/passwd", in / "linker" / "forces.cpp");
  fs::create_directories(dir / "elsewhere");
  std::ofstream(dir / "elsewhere" / "springs.cpp") << "// not in the class\n";
  fs::create_directory_symlink(dir / "elsewhere", in / "outside");
  for (const char* twin : {"Bob", "bob"}) {
    fs::create_directories(in / twin);
    std::ofstream(in / twin / "springs.cpp") << "// " << twin << "\n";
  }
  fs::create_directories(in / "a:b");  // empty too: not graded, but its id is made safe
  fs::create_directories(in / ".hidden");
  std::ofstream(in / ".hidden" / "springs.cpp") << "// hidden folders are not submissions\n";
  const Cmd r = run("batch " + in.string() + " --assignment a1 --out " + (dir / "out").string() +
                    " --jobs 2 --no-frames");
  EXPECT_EQ(r.status, 1) << "a student could not be graded: " << r.out;
  // The last line counts the graded and the not graded apart.
  EXPECT_NE(r.out.find("jelly-grade: 2 graded, 7 not graded (scores.csv's error column says why) "
                       "into "),
            std::string::npos)
      << r.out;
  const auto rows = csv_rows(dir / "out" / "scores.csv");
  std::set<std::string> ids;
  for (const auto& [id, row] : rows) ids.insert(id);
  EXPECT_EQ(ids, (std::set<std::string>{"Bob", "a_b", "alice", "bob~2", "empty", "linker",
                                        "notes.txt", "only-git", "outside"}))
      << read_text(dir / "out" / "scores.csv");
  ASSERT_TRUE(rows.count("alice"));
  EXPECT_EQ(rows.at("alice")[1], "80.00") << "the rest of the class is graded";
  const auto error_of = [&](const std::string& id) {
    return rows.count(id) ? rows.at(id).back() : std::string("(no row)");
  };
  EXPECT_NE(error_of("notes.txt").find("is a file, not a folder"), std::string::npos);
  EXPECT_NE(error_of("empty").find("an empty folder"), std::string::npos);
  EXPECT_NE(error_of("only-git").find("an empty folder"), std::string::npos);
  // A symlink out of the submission is not followed, and the rest of it is graded.
  ASSERT_TRUE(rows.count("linker"));
  EXPECT_NE(rows.at("linker")[1], "") << "graded";
  EXPECT_NE(record_text(dir / "out", "linker")
                .find("forces.cpp is a symlink to /etc/passwd, outside the submission: not "
                      "followed"),
            std::string::npos)
      << record_text(dir / "out", "linker");
  EXPECT_NE(read_text(dir / "out" / "students" / "linker" / "results.json")
                .find("error: is a symbolic link; submit the file itself"),
            std::string::npos)
      << "the build refuses the link itself";
  EXPECT_NE(error_of("outside").find("outside the class's folder: not followed"), std::string::npos)
      << error_of("outside");
  EXPECT_NE(error_of("Bob").find("the id Bob is also the id of bob"), std::string::npos)
      << error_of("Bob");
  EXPECT_NE(error_of("bob~2").find("the id bob is also the id of Bob"), std::string::npos)
      << error_of("bob~2");
  for (const char* id : {"notes.txt", "empty", "outside", "Bob", "bob~2", "a_b"}) {
    ASSERT_TRUE(rows.count(id)) << id;
    EXPECT_EQ(rows.at(id)[1], "") << id << ": no points rather than 0, so an import skips it";
    EXPECT_NE(record_text(dir / "out", id).find("\"status\": \"not graded\""), std::string::npos)
        << id;
  }
  EXPECT_NE(record_text(dir / "out", "a_b")
                .find("the id 'a:b' is not safe as a folder name: it "
                      "is a_b"),
            std::string::npos);
  EXPECT_NE(record_text(dir / "out", "bob~2").find("this row's id is bob~2"), std::string::npos);
}

// A Gradescope export as "Download Submissions" gives it: a zip of assignment_<n>_export/ with
// submission_metadata.yml and one folder per submission. Ids are the submitters' :sid: (else the
// email, else the folder); a group has a row per member; entries with '..' or an absolute path
// are refused, a symlink out of the submission is not followed (noted), and the rest is graded.
TEST(Grader, BatchReadsAGradescopeExportZip) {
  const fs::path dir = kWork / "batch-gradescope";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string root = "assignment_4711_export/";
  std::vector<ZipEntry> entries;
  entries.push_back({root + "submission_metadata.yml", R"(---
submission_101:
  :submitters:
  - &1
    :name: "Ana \u00d3 Lee"
    :sid: '1001'
    :email: ana@example.edu
    section_name: lab-2
  - :name: Ben 'B' Ode   # the second member
    :sid: 1002
    :email: ben@example.edu
  :created_at: 2026-11-01 10:00:00.000000000 Z
  :score: 80.0
  :results:
    tests:
    - name: "compiles"
      output: |-
        submission_999:
          :submitters:
          - :sid: '666'
  :history:
  - :created_at: 2026-10-31 09:00:00.000000000 Z
    :submitters:
    - :sid: '666'
submission_102:
  :submitters:
  - :name: Cy
    :email: cy@example.edu
submission_103:
  :submitters:
  - :name: Dee
    :sid: '1004'
submission_104:
  :submitters:
  - :name: Eve
    :sid: '1005'
submission_105:
  :submitters:
  - *1
submission_106:
  :submitters: []
)"});
  for (const std::string& f : kTaskFiles) {
    std::ifstream src(reference_dir("a1") / f, std::ios::binary);
    std::stringstream text;
    text << src.rdbuf();
    entries.push_back({root + "submission_101/src/" + f, text.str()});
  }
  entries.push_back({root + "submission_102/", ""});  // a folder and nothing in it
  entries.push_back({root + "submission_103/springs.cpp", "// Dee\n"});
  entries.push_back({root + "submission_103/forces.cpp", "/etc/passwd", true});
  entries.push_back({root + "submission_104/springs.cpp", "// Eve\n"});
  entries.push_back({root + "submission_104/../../escaped.txt", "out of the export\n"});
  entries.push_back({"/absolute.txt", "out of the export\n"});
  entries.push_back({root + "submission_105/springs.cpp", "// Ana again\n"});
  entries.push_back({root + "submission_106/springs.cpp", "// nobody\n"});
  write_zip(dir / "export.zip", entries);
  const fs::path out = dir / "out";
  const Cmd r = run("batch " + (dir / "export.zip").string() + " --out " + out.string() +
                    " --jobs 2 --no-frames");
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_FALSE(fs::exists(dir / "escaped.txt"));
  EXPECT_FALSE(fs::exists(out / "escaped.txt"));
  EXPECT_FALSE(fs::exists("/absolute.txt"));
  const auto rows = csv_rows(out / "scores.csv");
  std::set<std::string> ids;
  for (const auto& [id, row] : rows) ids.insert(id);
  // 1001 twice: Ana in her group and (through the alias) in submission_105.
  EXPECT_EQ(ids, (std::set<std::string>{"1001", "1001~2", "1002", "1004", "1005", "cy@example.edu",
                                        "submission_106"}))
      << read_text(out / "scores.csv");
  // The group: one row per member, each graded from the group's files.
  ASSERT_TRUE(rows.count("1002"));
  EXPECT_EQ(rows.at("1002")[1], "80.00") << r.out;
  EXPECT_EQ(rows.at("1002")[3], "100.00");
  const std::string ben = record_text(out, "1002");
  EXPECT_NE(ben.find("\"name\": \"Ben 'B' Ode\""), std::string::npos) << ben;
  EXPECT_NE(ben.find("\"email\": \"ben@example.edu\""), std::string::npos) << ben;
  EXPECT_NE(ben.find("group submission submission_101 with Ana \u00d3 Lee (1001)"),
            std::string::npos)
      << ben;
  EXPECT_NE(read_text(out / "scores.csv").find(",Ana \u00d3 Lee,ana@example.edu,"),
            std::string::npos);
  // Ana is in two submissions: neither row is graded, each names the other.
  EXPECT_NE(rows.at("1001").back().find("the id 1001 is also the id of submission_105"),
            std::string::npos)
      << rows.at("1001").back();
  EXPECT_NE(rows.at("1001~2").back().find("the id 1001 is also the id of submission_101"),
            std::string::npos);
  EXPECT_NE(rows.at("cy@example.edu").back().find("an empty folder"), std::string::npos)
      << rows.at("cy@example.edu").back();
  EXPECT_NE(record_text(out, "cy@example.edu").find("no student id (:sid:)"), std::string::npos);
  EXPECT_NE(rows.at("1004")[1], "") << "graded, the link not followed";
  EXPECT_NE(record_text(out, "1004")
                .find("forces.cpp is a symlink to /etc/passwd, outside the "
                      "submission: not followed"),
            std::string::npos)
      << record_text(out, "1004");
  EXPECT_NE(rows.at("1005").back().find("the zip's entry '" + root +
                                        "submission_104/../../escaped.txt' has a '..' component: "
                                        "refused"),
            std::string::npos)
      << rows.at("1005").back();
  EXPECT_NE(r.out.find("the zip's entry '/absolute.txt' has an absolute path: refused"),
            std::string::npos)
      << r.out;
  EXPECT_NE(record_text(out, "submission_106").find("names no submitter for submission_106"),
            std::string::npos);
  // The class files hold no absolute path (the export was extracted under --out).
  EXPECT_EQ(read_text(out / "scores.csv").find(dir.string()), std::string::npos);
}

// submission_metadata.yml that is not what Gradescope writes: the file and the line are named
// (yaml-cpp's message, here an alias to no anchor).
TEST(Grader, BatchNamesTheFileAndLineOfABadSubmissionMetadata) {
  const fs::path dir = kWork / "batch-bad-metadata";
  fs::remove_all(dir);
  fs::create_directories(dir / "export" / "submission_1");
  std::ofstream(dir / "export" / "submission_1" / "springs.cpp") << "// x\n";
  std::ofstream(dir / "export" / "submission_metadata.yml")
      << "submission_1:\n  :submitters:\n  - :name: *nobody\n";
  const Cmd r = run("batch " + (dir / "export").string() + " --assignment a1 --out " +
                    (dir / "out").string());
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("submission_metadata.yml:3: the referenced anchor is not defined"),
            std::string::npos)
      << r.out;
}

// GitHub Classroom: `gh classroom clone student-repos` makes <assignment>-submissions/ with a clone
// <assignment>-<username> per student; the id is the username, even one with a '-'.
TEST(Grader, BatchTakesGitHubClassroomUsernamesAsIds) {
  const fs::path dir = kWork / "batch-classroom" / "a1-jelly-submissions";
  fs::remove_all(dir.parent_path());
  for (const char* who : {"a1-jelly-mary-jane", "a1-jelly-mary-ann"}) {
    fs::create_directories(dir / who / ".git" / "objects");
    std::ofstream(dir / who / ".git" / "HEAD") << "ref: refs/heads/main\n";
  }
  const fs::path out = dir.parent_path() / "out";
  const Cmd r = run("batch " + dir.string() + " --assignment a1 --out " + out.string());
  EXPECT_EQ(r.status, 1) << "both clones are empty: " << r.out;
  EXPECT_NE(r.out.find("jelly-grade: 0 graded, 2 not graded"), std::string::npos)
      << "none graded is not \"graded 2\": " << r.out;
  const auto rows = csv_rows(out / "scores.csv");
  EXPECT_EQ(rows.size(), 2u) << read_text(out / "scores.csv");
  EXPECT_TRUE(rows.count("mary-jane")) << read_text(out / "scores.csv");
  EXPECT_TRUE(rows.count("mary-ann")) << read_text(out / "scores.csv");
  EXPECT_NE(record_text(out, "mary-ann")
                .find("GitHub Classroom repository a1-jelly-mary-ann: the id is the username "
                      "mary-ann (the prefix a1-jelly- every folder shares stripped)"),
            std::string::npos)
      << record_text(out, "mary-ann");
  // Elsewhere than <assignment>-submissions/, the prefix all the folders share goes.
  const fs::path moved = dir.parent_path() / "clones";
  fs::rename(dir, moved);
  fs::create_directories(moved / "a1-jelly-zed" / ".git");
  std::ofstream(moved / "a1-jelly-zed" / ".git" / "HEAD") << "ref: refs/heads/main\n";
  const Cmd r2 = run("batch " + moved.string() + " --assignment a1 --out " + out.string());
  const auto rows2 = csv_rows(out / "scores.csv");
  std::set<std::string> ids;
  for (const auto& [id, row] : rows2) ids.insert(id);
  EXPECT_EQ(ids, (std::set<std::string>{"mary-ann", "mary-jane", "zed"})) << r2.out;
}

// A batch, like every grading run, says first which sandbox it grades in (the guide tells the
// instructor to read it there).
TEST(Grader, BatchSaysWhichSandboxItGradesIn) {
  const fs::path dir = kWork / "batch-sandbox";
  fs::remove_all(dir);
  fs::create_directories(dir / "in" / "empty");
  const Cmd r = run("batch " + (dir / "in").string() + " --assignment a1 --out " +
                    (dir / "out").string() + " --isolation none");
  EXPECT_NE(r.out.find("jelly-grade: sandbox: none"), std::string::npos) << r.out;
}

namespace {

// A1's task files for a small class: the reference's, with `stub` (a file name, or "") taken from
// the stubs instead.
std::map<std::string, std::string> a1_files(const std::string& stub = "") {
  std::map<std::string, std::string> out;
  for (const std::string& f : kTaskFiles)
    out[f] = read_text((f == stub ? kSource / "assignments" / "a1" : reference_dir("a1")) / f);
  return out;
}

// scores.csv's rows without the name column (an LMS download gives names, a folder none).
std::map<std::string, std::vector<std::string>> rows_but_names(const fs::path& file) {
  std::map<std::string, std::vector<std::string>> rows = csv_rows(file);
  std::ifstream in(file);
  std::string header;
  std::getline(in, header);
  const auto at = header.find(",name,");
  const auto column =
      static_cast<std::size_t>(std::count(header.begin(), header.begin() + at, ','));
  for (auto& [id, row] : rows)
    if (row.size() > column + 1) row.erase(row.begin() + static_cast<long>(column) + 1);
  return rows;
}

// The last line of a batch's output.
std::string last_line(const std::string& out) {
  std::string s = out;
  while (!s.empty() && s.back() == '\n') s.pop_back();
  return s.substr(s.rfind('\n') + 1);
}

}  // namespace

// Canvas's "Download Submissions" and Moodle's "Download all submissions", each as a folder and as
// the zip they come in, made here in those systems' own naming (Canvas lib/content_zipper.rb,
// Moodle mod/assign/classes/downloader.php): each student's files are found by their names and
// graded to the same scores.csv as the same students in folders named by their ids. Canvas: a late
// submission (LATE, or older downloads' `late`), a file resubmitted (-1, the later); Moodle: a
// folder per plugin (file, onlinetext), with (before 4.1) or without its trailing '_', files in a
// subfolder. An entry named as no student's is a row not graded, saying why; the last line counts
// the graded and the not graded apart.
TEST(Grader, BatchReadsCanvasAndMoodleDownloadsAsTheSameStudentsInFolders) {
  const fs::path dir = kWork / "batch-lms";
  fs::remove_all(dir);
  // alice: the reference; bob: the stub forces.cpp; carol: the reference.
  const std::map<std::string, std::map<std::string, std::string>> students = {
      {"11111", a1_files()}, {"22222", a1_files("forces.cpp")}, {"33333", a1_files()}};
  const auto write = [](const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
  };
  for (const auto& [id, files] : students)
    for (const auto& [f, text] : files) write(dir / "folders" / id / f, text);

  // Canvas: <name>[_LATE]_<user id>_<file id>_<file>, one flat folder.
  std::vector<ZipEntry> canvas;
  int file_id = 90000;
  const std::map<std::string, std::string> canvas_prefix = {{"11111", "liddellalice_11111_"},
                                                            {"22222", "odebob_late_22222_"},
                                                            {"33333", "smithcarol_LATE_33333_"}};
  for (const auto& [id, files] : students)
    for (const auto& [f, text] : files) {
      const std::string name = canvas_prefix.at(id) + std::to_string(++file_id) + "_" + f;
      if (id != "33333" || f != "forces.cpp") {
        canvas.push_back({name, text});
        continue;
      }
      // carol handed forces.cpp in twice: Canvas named the later one forces-1.cpp.
      canvas.push_back({name, read_text(kSource / "assignments" / "a1" / f)});
      canvas.push_back({canvas_prefix.at(id) + std::to_string(++file_id) + "_forces-1.cpp", text});
    }
  canvas.push_back({"odebob_late_22222_text.html", "<p>see my files</p>\n"});
  canvas.push_back({"notes.txt", "not a student's\n"});
  // Moodle: <Full Name>_<participant id>_assignsubmission_<plugin>[_]/<the file's path>.
  std::vector<ZipEntry> moodle;
  const std::map<std::string, std::string> moodle_folder = {
      {"11111", "Alice Liddell_11111_assignsubmission_file/"},
      {"22222", "Bob Ode_22222_assignsubmission_file_/"},
      {"33333", "Carol Smith_33333_assignsubmission_file/src/"}};
  for (const auto& [id, files] : students)
    for (const auto& [f, text] : files) moodle.push_back({moodle_folder.at(id) + f, text});
  moodle.push_back(
      {"Bob Ode_22222_assignsubmission_onlinetext_/onlinetext.html", "<p>see my files</p>\n"});
  moodle.push_back({"Dan_Rest/springs.cpp", "// a folder named as no student's\n"});
  for (const auto& [name, entries] : {std::pair{"canvas", canvas}, std::pair{"moodle", moodle}}) {
    for (const ZipEntry& e : entries) write(dir / name / e.name, e.data);
    write_zip(dir / (std::string(name) + ".zip"), entries);
  }

  const auto batch = [&](const std::string& in) {
    const Cmd r = run("batch " + (dir / in).string() + " --assignment a1 --out " +
                      (dir / ("out-" + in)).string() + " --jobs 2 --no-frames");
    return r;
  };
  const Cmd folders = batch("folders");
  ASSERT_EQ(folders.status, 0) << folders.out;
  EXPECT_EQ(last_line(folders.out).rfind("jelly-grade: 3 graded, 0 not graded into ", 0), 0u)
      << folders.out;
  const auto expected = rows_but_names(dir / "out-folders" / "scores.csv");
  ASSERT_EQ(expected.size(), 3u);
  EXPECT_EQ(expected.at("11111")[1], "80.00");
  EXPECT_NE(expected.at("22222")[1], "80.00") << "bob's stub forces.cpp costs points";
  for (const char* in : {"canvas", "canvas.zip", "moodle", "moodle.zip"}) {
    SCOPED_TRACE(in);
    const Cmd r = batch(in);
    EXPECT_EQ(r.status, 1) << "one entry names no student: " << r.out;
    EXPECT_EQ(last_line(r.out).rfind("jelly-grade: 3 graded, 1 not graded (scores.csv's error "
                                     "column says why) into ",
                                     0),
              0u)
        << r.out;
    const fs::path out = dir / ("out-" + std::string(in));
    auto rows = rows_but_names(out / "scores.csv");
    const std::string stray = std::string(in).rfind("canvas", 0) == 0 ? "notes.txt" : "Dan_Rest";
    ASSERT_TRUE(rows.count(stray)) << read_text(out / "scores.csv");
    EXPECT_EQ(rows.at(stray)[1], "") << "no points: an import leaves it alone";
    EXPECT_NE(rows.at(stray).back().find("not named as these name a student's entry"),
              std::string::npos)
        << rows.at(stray).back();
    rows.erase(stray);
    EXPECT_EQ(rows, expected) << read_text(out / "scores.csv");
    // The name column holds the name the download gives.
    const std::string csv = read_text(out / "scores.csv");
    EXPECT_NE(csv.find(std::string(in).rfind("canvas", 0) == 0 ? ",smithcarol," : ",Carol Smith,"),
              std::string::npos)
        << csv;
  }
  EXPECT_NE(record_text(dir / "out-canvas", "33333")
                .find("Canvas marked the submission late (LATE in its names)"),
            std::string::npos);
  EXPECT_NE(record_text(dir / "out-canvas", "22222").find("Canvas marked the submission late"),
            std::string::npos)
      << "older downloads' lower-case late";
  EXPECT_NE(read_text(dir / "out-canvas" / "students" / "33333" / "results.json")
                .find("forces-1.cpp was graded as forces.cpp"),
            std::string::npos)
      << "the later of carol's two forces.cpp";
  EXPECT_NE(record_text(dir / "out-moodle", "22222").find("Moodle's participant id"),
            std::string::npos);
}

// A2's bonus reaches the gradebook: scores.csv's `total` is points + bonus, the column to import;
// `hand_graded_max` is the manifest's hand_graded_points (20); max_points stays autograded_total.
TEST(Grader, ScoresCsvTotalCarriesTheBonus) {
  const fs::path dir = kWork / "batch-a2-total";
  fs::remove_all(dir);
  const toml::table manifest =
      toml::parse_file((kSource / "assignments" / "a2" / "assignment.toml").string());
  for (const char* who : {"with-friction", "without-friction"})
    for (const toml::node& f : *manifest["files"].as_array()) {
      const std::string file = f.value_or(std::string());
      const bool stub = std::string(who) == "without-friction" && file == "friction.cpp";
      fs::create_directories(dir / "in" / who);
      fs::copy_file((stub ? kSource / "assignments" / "a2" : reference_dir("a2")) / file,
                    dir / "in" / who / file);
    }
  const Cmd r = run("batch " + (dir / "in").string() + " --assignment a2 --out " +
                    (dir / "out").string() + " --jobs 2 --no-frames");
  ASSERT_EQ(r.status, 0) << r.out;
  std::ifstream in(dir / "out" / "scores.csv");
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("student,points,max_points,percent,bonus,total,hand_graded,"
                         "hand_graded_max,compiled,",
                         0),
            0u)
      << header;
  const auto rows = csv_rows(dir / "out" / "scores.csv");
  ASSERT_TRUE(rows.count("with-friction") && rows.count("without-friction"))
      << read_text(dir / "out" / "scores.csv");
  // student, points, max_points, percent, bonus, total, hand_graded, hand_graded_max
  EXPECT_EQ(std::vector<std::string>(rows.at("with-friction").begin(),
                                     rows.at("with-friction").begin() + 8),
            (std::vector<std::string>{"with-friction", "80.00", "80.00", "100.00", "5.00", "85.00",
                                      "", "20.00"}));
  // Without the friction task: no bonus, and total is the points.
  const std::vector<std::string>& plain = rows.at("without-friction");
  EXPECT_EQ(plain[4], "0.00") << read_text(dir / "out" / "scores.csv");
  EXPECT_EQ(plain[5], plain[1]);
  EXPECT_EQ(plain[7], "20.00");
}

// The class report (class.json; class.md and class.html to project; class-instructor.md and
// class-instructor.html) of a small class: the reference, the stubs, two of the grader's mutants, a
// file that does not compile (its message quotes HTML), a function that never returns and a
// missing task file (in a folder whose name is HTML), and explicit Euler without h (the course
// scene blows up).
TEST(Grader, ClassReportCountsWhatTheClassGotWrong) {
  const fs::path dir = kWork / "class-report";
  fs::remove_all(dir);
  const fs::path in = dir / "in";
  const std::vector<std::string> files = {"springs.cpp", "forces.cpp", "collision.cpp",
                                          "contact.cpp", "integrators.cpp"};
  auto reference = [&](const std::string& id) {
    fs::create_directories(in / id);
    for (const std::string& f : files) fs::copy_file(reference_dir("a1") / f, in / id / f);
    return in / id;
  };
  // A mutant applied as `jelly-grade mutants` applies it (each [[replace]] once).
  auto mutant = [&](const std::string& id, const std::string& name) {
    const toml::table t = toml::parse_file(
        (kSource / "assignments" / "a1" / "grader" / "mutants" / (name + ".toml")).string());
    const std::string file = t["file"].value_or(std::string());
    const fs::path path = reference(id) / file;
    std::string text = read_text(path);
    for (const toml::node& n : *t["replace"].as_array()) {
      const std::string find = (*n.as_table())["find"].value_or(std::string());
      const auto at = text.find(find);
      ASSERT_NE(at, std::string::npos) << name << " no longer applies";
      text.replace(at, find.size(), (*n.as_table())["with"].value_or(std::string()));
    }
    std::ofstream(path, std::ios::binary) << text;
  };
  const std::string html_id = "f-<b onclick=x>&missing";  // no slash: one folder
  // Its id: the reader makes ids safe as folder names (< and > go), '&' stays for the escaping.
  const std::string safe_id = "f-_b onclick=x_&missing";
  reference("a-reference");
  mutant("b-mutant-t1", "t1-duplicates");
  mutant("c-mutant-t13", "t13-k4-from-k2");
  mutant("a2-mutant-t10", "t10-no-h");  // its course scene blows up (the first to fail it)
  std::ofstream(reference("d-no-compile") / "forces.cpp", std::ios::app)
      << "\n#error <script>alert(\"class\")</script>\n";
  fs::copy_file(kHostile / "infinite_loop" / "integrators.cpp",
                reference("e-loop") / "integrators.cpp", fs::copy_options::overwrite_existing);
  fs::remove(reference(html_id) / "contact.cpp");
  fs::copy(kSource / "assignments" / "a1", in / "z-stubs", fs::copy_options::recursive);
  const Cmd r = run("batch " + in.string() + " --assignment a1 --out " + (dir / "out").string() +
                    " --jobs 2 --timeout 3 --no-frames");
  ASSERT_EQ(r.status, 0) << r.out;

  const Json c = read_json(dir / "out" / "class.json");
  EXPECT_EQ(c["students"], 8);
  EXPECT_EQ(c["graded"], 8);
  EXPECT_EQ(c["score"]["full_marks"], 1) << "the reference";
  EXPECT_EQ(c["score"]["histogram"][0]["count"], 1) << "the stubs";
  auto failed_case = [&](const std::string& task, const std::string& id) -> Json {
    for (const Json& t : c["tasks"])
      if (t["id"] == task)
        for (const Json& fc : t["failed_cases"])
          if (fc["case"] == id) return fc;
    return Json();
  };
  auto first_failure = [&](const std::string& student, const std::string& id) {
    const Json rec = read_json(dir / "out" / "students" / student / "record.json");
    for (const Json& k : rec["cases"])
      if (k["id"] == id && !k["failures"].empty()) return k["failures"][0].get<std::string>();
    return std::string("(no failure of ") + id + ")";
  };
  // The mutants' cases: failed by the mutant and the stubs; the example is the mutant (first by
  // id) with its first failure message, as its own record has it.
  for (const auto& [task, id, student] : std::vector<std::array<std::string, 3>>{
           {"A1.T1", "a1.t1.structural.n3", "b-mutant-t1"},
           {"A1.T13", "a1.t13.rk4.single_step", "c-mutant-t13"}}) {
    const Json fc = failed_case(task, id);
    ASSERT_TRUE(fc.is_object()) << id << " not among " << task << "'s failed cases:\n" << c.dump(1);
    EXPECT_EQ(fc["students"], 2) << id << ": the mutant and the stubs";
    EXPECT_EQ(fc["example"]["student"], student);
    EXPECT_EQ(fc["example"]["message"], first_failure(student, id)) << id;
  }
  // A case only the stubs fail (k4 from k2 keeps the energy test): counted once.
  EXPECT_EQ(failed_case("A1.T13", "a1.t13.rk4.energy")["students"], 1);
  // A task every compiled student but the stubs passes (the loop times out, not fails).
  EXPECT_EQ(failed_case("A1.T5", "a1.t5.damper_force.values")["example"]["student"], "z-stubs");

  ASSERT_EQ(c["did_not_compile"].size(), 1u) << c["did_not_compile"].dump(1);
  EXPECT_EQ(c["did_not_compile"][0]["student"], "d-no-compile");
  EXPECT_EQ(c["did_not_compile"][0]["file"], "forces.cpp");
  EXPECT_NE(c["did_not_compile"][0]["message"].get<std::string>().find("<script>"),
            std::string::npos)
      << "the compiler's error line: " << c["did_not_compile"][0].dump();
  ASSERT_EQ(c["timed_out_or_crashed"].size(), 1u) << c["timed_out_or_crashed"].dump(1);
  EXPECT_EQ(c["timed_out_or_crashed"][0]["student"], "e-loop");
  EXPECT_EQ(c["timed_out_or_crashed"][0]["abnormal"], "timed out");
  EXPECT_EQ(c["timed_out_or_crashed"][0]["first_case"].get<std::string>().rfind("a1.t13.", 0), 0u);
  EXPECT_TRUE(c["could_not_grade"].empty());
  ASSERT_EQ(c["missing_files"]["students"].size(), 1u);
  EXPECT_EQ(c["missing_files"]["students"][0]["student"], safe_id);
  EXPECT_EQ(c["missing_files"]["students"][0]["files"], Json::array({"contact.cpp"}));

  // d-no-compile's forces.cpp did not compile: the course scene ran with its stub and failed,
  // which follows from the compile error and is not counted again.
  for (const Json& t : c["tasks"])
    for (const Json& fc : t["failed_cases"])
      if (fc["case"] == "a1.course.scene") {
        int failed = 0;
        for (const fs::directory_entry& e : fs::directory_iterator(dir / "out" / "students")) {
          if (e.path().filename() == "d-no-compile") continue;
          const Json record = read_json(e.path() / "record.json");
          for (const Json& k : record["cases"])
            if (k["id"] == "a1.course.scene" && k["status"] == "failed" && k["abnormal"] == "")
              ++failed;
        }
        EXPECT_EQ(fc["students"], failed) << fc.dump(1);
        EXPECT_NE(fc["example"]["student"], "d-no-compile");
      }
  // The mutants' mistakes in the hints' words (hints.json), one student each.
  auto mistake = [&](const std::string& task, const std::string& what) {
    for (const Json& t : c["tasks"])
      if (t["id"] == task)
        for (const Json& m : t["known_mistakes"])
          if (m["mistake"] == what) return m["students"].get<int>();
    return 0;
  };
  EXPECT_EQ(mistake("A1.T1", "every (1,0,0) structural spring built twice"), 1) << c.dump(1);
  EXPECT_EQ(mistake("A1.T13", "k4 evaluated from k2 instead of k3"), 1);

  const std::string md = read_text(dir / "out" / "class-instructor.md");
  for (const char* section :
       {"# What the class got wrong: The jelly cube", "## Scores", "## Tasks",
        "## What failed, task by task", "### A1.T13", "## Did not compile",
        "- d-no-compile: forces.cpp did not compile", "## Timed out or crashed",
        "- e-loop: timed out in ", "## Could not be graded\n\nNone.", "## Missing task files",
        "**Missing task files: 1 student** (contact.cpp 1)"})
    EXPECT_NE(md.find(section), std::string::npos) << section << "\n" << md;
  const std::string html = read_text(dir / "out" / "class-instructor.html");
  EXPECT_EQ(html.find("<script"), std::string::npos) << "the compile error's text is escaped";
  EXPECT_EQ(html.find("<b onclick"), std::string::npos) << "the folder name is escaped";
  EXPECT_NE(html.find("f-_b onclick=x_&amp;missing"), std::string::npos);
  EXPECT_NE(md.find("- f-\\_b onclick=x\\_&amp;missing: contact.cpp"), std::string::npos) << md;
  EXPECT_NE(html.find("&lt;script&gt;alert(&quot;class&quot;)&lt;/script&gt;"), std::string::npos);
  // No path of this machine in the class files (a merge of shards elsewhere gives the same
  // bytes).
  const std::string lecture_md = read_text(dir / "out" / "class.md");
  const std::string lecture_html = read_text(dir / "out" / "class.html");
  for (const std::string& text :
       {html, md, read_text(dir / "out" / "class.json"), lecture_md, lecture_html})
    EXPECT_EQ(text.find(kWork.string()), std::string::npos);

  // The lecture's view (class.md, class.html): the assignment's name, what went wrong counted,
  // and no student and no hidden test: no id (the folder names), no hidden case's id or title,
  // no number of its inputs or expected values (as the grader prints them, %.10g), and nothing
  // of the hidden failures' messages (their numbers as the runner prints them too).
  EXPECT_NE(lecture_md.find("# What the class got wrong: The jelly cube"), std::string::npos);
  EXPECT_NE(lecture_html.find("<h1>What the class got wrong: The jelly cube</h1>"),
            std::string::npos);
  EXPECT_NE(lecture_md.find("of the class (1 student)**: every (1,0,0) structural spring built "
                            "twice"),
            std::string::npos)
      << lecture_md;
  EXPECT_NE(lecture_md.find("- did not compile: 1 student ("), std::string::npos) << lecture_md;
  // A course scene the stability detector stopped, said plainly, in every view and the record.
  EXPECT_EQ(first_failure("a2-mutant-t10", "a1.course.scene")
                .rfind("the stability detector fired before its first sample (the run was to "
                       "last 10 s): the simulation blew up",
                       0),
            0u)
      << first_failure("a2-mutant-t10", "a1.course.scene");
  EXPECT_EQ(first_failure("d-no-compile", "a1.course.scene")
                .rfind("the stability detector fired shortly after t = ", 0),
            0u)
      << first_failure("d-no-compile", "a1.course.scene");
  for (const std::string& text : {md, lecture_md})
    EXPECT_NE(text.find("the stability detector fired before its first sample"), std::string::npos)
        << "the course scene's example\n"
        << text;
  for (const std::string& text : {html, md, lecture_md, lecture_html})
    EXPECT_EQ(text.find("without the stability detector firing"), std::string::npos);
  // A number the public data has too (a time step, a cube's size) is no secret.
  std::set<std::string> hidden, brief, shown;
  std::function<void(const Json&, std::set<std::string>&, const char*, std::size_t)> numbers =
      [&](const Json& j, std::set<std::string>& into, const char* format, std::size_t least) {
        if (j.is_number()) {
          char b[40];
          std::snprintf(b, sizeof b, format, j.get<double>());
          if (std::string(b).size() >= least) into.insert(b);
        } else if (j.is_structured()) {
          for (const Json& e : j) numbers(e, into, format, least);
        }
      };
  for (const char* vis : {"public", "hidden"})
    for (const fs::directory_entry& e : fs::directory_iterator(
             vis == std::string("public") ? kSource / "assignments" / "a1" / "grader" / "data" / vis
                                          : kSource / "grader" / "data" / "a1" / vis)) {
      const Json ref = read_json(e.path());
      std::set<std::string>& into = vis == std::string("public") ? shown : hidden;
      if (&into == &hidden) hidden.insert(ref["case_id"].get<std::string>());
      for (const char* key : {"params", "input"}) {
        numbers(ref.value(key, Json()), into, "%.10g", &into == &hidden ? 6 : 1);
        if (&into == &shown) numbers(ref.value(key, Json()), shown, "%.3g", 1);
        if (&into == &shown) numbers(ref.value(key, Json()), shown, "%.4g", 1);
        if (&into == &hidden) numbers(ref.value(key, Json()), brief, "%.3g", 5);
        if (&into == &hidden) numbers(ref.value(key, Json()), brief, "%.4g", 5);
      }
      for (const auto& [name, out] : ref["outputs"].items())
        numbers(out.value("value", Json()), into, "%.10g", &into == &hidden ? 6 : 1);
    }
  for (const std::string& v : shown) hidden.erase(v);
  for (const std::string& v : shown) brief.erase(v);
  std::size_t in_instructor = 0;
  for (const std::string& v : hidden) in_instructor += md.find(v) != std::string::npos;
  EXPECT_GT(in_instructor, 0u) << "the instructor's view shows hidden tests; the check can fail";
  for (const fs::directory_entry& e :
       fs::directory_iterator(kSource / "assignments" / "a1" / "grader" / "cases")) {
    const toml::table t = toml::parse_file(e.path().string());
    if (const toml::array* cases = t["case"].as_array())
      for (const toml::node& n : *cases)
        if ((*n.as_table())["visibility"].value_or(std::string()) == "hidden")
          hidden.insert((*n.as_table())["title"].value_or(std::string()));
  }
  // The hidden failures' messages: the numbers of their inputs as the runner prints them.
  for (const Json& t : c["tasks"])
    for (const Json& fc : t["failed_cases"])
      if (fc["hidden"].get<bool>()) {
        std::istringstream words(fc["example"]["message"].get<std::string>());
        for (std::string w; words >> w;) {
          w.erase(0, w.find_first_of("-0123456789"));
          w = w.substr(0, w.find_first_not_of("0123456789.e-"));
          if (brief.count(w) && !shown.count(w)) hidden.insert(w);
        }
      }
  for (const std::string& text : {lecture_md, lecture_html}) {
    for (const std::string& v : hidden)
      EXPECT_EQ(text.find(v), std::string::npos) << "hidden: " << v;
    for (const fs::directory_entry& e : fs::directory_iterator(dir / "out" / "students"))
      for (const std::string& id :
           {e.path().filename().string(), std::string("f-_b onclick=x_&amp;missing")})
        EXPECT_EQ(text.find(id), std::string::npos) << "student: " << id;
  }
}

TEST(Grader, GradescopeZipHasTheEntryPointsAndNoSolutions) {
  const fs::path zip = kWork / "autograder.zip";
  const Cmd r = run("gradescope-zip " + zip.string() + " --assignment a1");
  ASSERT_EQ(r.status, 0) << r.out;
  FILE* p = popen(("unzip -Z1 " + jelly::testing::shell_quoted(zip.string())).c_str(), "r");
  std::string list;
  char buf[4096];
  std::size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) list.append(buf, n);
  pclose(p);
  // One folder: Gradescope extracts the zip into /autograder/source, where setup.sh runs
  // `cmake -S .`, so the framework's CMakeLists.txt is at the top beside the two scripts.
  list.insert(0, "\n");  // every entry is "\n" + path + "\n"
  EXPECT_NE(list.find("\nsetup.sh\n"), std::string::npos) << list;
  EXPECT_NE(list.find("\nrun_autograder\n"), std::string::npos);
  EXPECT_NE(list.find("\nCMakeLists.txt\n"), std::string::npos);
  EXPECT_NE(list.find("\ngrader/data/a1/hidden/"), std::string::npos);
  EXPECT_NE(list.find("\nassignments/a1/assignment.toml\n"), std::string::npos);
  EXPECT_NE(list.find("\nassignments/a1/grader/cases/"), std::string::npos);
  EXPECT_NE(list.find("\nthird_party/cli11/include/CLI/CLI.hpp\n"), std::string::npos);
  EXPECT_EQ(list.find("\nsource/"), std::string::npos) << "a source/ folder inside the zip";
  EXPECT_EQ(list.find("solutions/"), std::string::npos);
  EXPECT_EQ(list.find("grader/tests/"), std::string::npos);
  // The mutants quote the reference: no assignment's may ship.
  EXPECT_EQ(list.find("grader/mutants/"), std::string::npos) << list;
}

// A1.T1 with one spring missing and one extra (issue 12): the failure names both by their grid
// coordinates, and the terminal's "(N more: --verbose, ...)" hint is true: with --verbose every
// failure shows and the hint is gone (on a compiled submission and on a prebuilt runner, the
// IDE's selfcheck target, whose report is the same line for line).
TEST(Grader, SpringFailuresNameTheMissingAndExtraSpringsAndVerboseShowsTheRest) {
  const fs::path sub = submission("spring_names");
  const fs::path file = sub / "nested" / "src" / "springs.cpp";
  std::string text = read_text(file);
  const std::string call = "add_forward_springs(cube, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, out);";
  const auto at = text.find(call);
  ASSERT_NE(at, std::string::npos) << "solutions/a1/springs.cpp changed: update this test";
  text.insert(
      at + call.size(),
      "\n  out.erase(out.begin());  // the spring (0,0,0)-(1,0,0)\n"
      "  out.push_back(Spring{cube.index(0, 0, 0), cube.index(1, 1, 0),\n"
      "                       (cube.position(1, 1, 0) - cube.position(0, 0, 0)).norm()});\n");
  std::ofstream(file, std::ios::binary) << text;
  const fs::path out = kWork / "out" / "spring_names";
  fs::remove_all(out);
  setenv("JELLY_GRADE_KEEP_WORK", "1", 1);
  const Cmd plain =
      run("grade " + sub.string() + " --visibility public --format terminal --out " + out.string());
  unsetenv("JELLY_GRADE_KEEP_WORK");
  ASSERT_EQ(plain.status, 0) << plain.out;
  // The task's first failed test (the 2×2×2 cube) is expanded: its first two reasons name the
  // springs, the hint counts the rest; the next failed test (3×3×3) is one line.
  const std::string n2 = "[a1.t1.structural.n2]", n3 = "[a1.t1.structural.n3]";
  ASSERT_NE(plain.out.find(n2), std::string::npos) << plain.out;
  const std::string first =
      plain.out.substr(plain.out.find(n2), plain.out.find(n3) - plain.out.find(n2));
  EXPECT_NE(first.find("allowed 0 by tolerance 'exact'); missing: (0,0,0)–(1,0,0)\n"),
            std::string::npos)
      << plain.out;
  EXPECT_NE(first.find("allowed 0 by tolerance 'exact'); yours: (0,0,0)–(1,1,0)\n"),
            std::string::npos)
      << plain.out;
  EXPECT_NE(first.find("(1 more: --verbose, or the selfcheck-verbose target)"), std::string::npos)
      << plain.out;
  EXPECT_NE(plain.out.find(n3 + "\n           ✗ "), std::string::npos)
      << "the second failed test is one line:\n"
      << plain.out;
  EXPECT_EQ(count(plain.out, "pair_set"), 0u) << "the third failure shows only with --verbose:\n"
                                              << plain.out;

  fs::path runner;
  for (const auto& e : fs::recursive_directory_iterator(out / ".work"))
    if (e.path().filename() == "runner" && e.is_regular_file()) runner = e.path();
  ASSERT_FALSE(runner.empty()) << "no built runner kept under " << out / ".work";
  const std::string args = "grade " + sub.string() +
                           " --visibility public --format terminal --runner " + runner.string();
  const Cmd prebuilt = run(args + " --out " + (out / "prebuilt").string());
  EXPECT_NE(prebuilt.out.find("(1 more: --verbose, or the selfcheck-verbose target)"),
            std::string::npos)
      << prebuilt.out;
  const Cmd verbose = run(args + " --verbose --out " + (out / "verbose").string());
  EXPECT_EQ(verbose.out.find(" more: --verbose"), std::string::npos) << verbose.out;
  EXPECT_NE(verbose.out.find("pair_set"), std::string::npos) << verbose.out;
  EXPECT_NE(verbose.out.find("missing: (0,0,0)–(1,0,0)"), std::string::npos) << verbose.out;
  // --verbose expands every failed test: the 3×3×3 cube's reasons too.
  const std::string all = verbose.out.substr(verbose.out.find(n3));
  EXPECT_NE(all.find("expected 18, got 17 (difference 1, allowed 0 by tolerance 'exact'); "
                     "missing: (0,0,0)–(1,0,0)\n"),
            std::string::npos)
      << verbose.out;
}

// ---- --assignment: which assignment a command works on (grade-config.json's "assignments") ----
namespace {

// A copy of this build's grade-config.json with a second assignment "zz" beside a1 (a folder with
// a manifest of its own files; never graded here), or with `edit` applied to it.
fs::path config_with(const std::string& name, const std::function<void(Json&)>& edit) {
  const fs::path dir = kWork / "configs" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  Json cfg = read_json(fs::path(JELLY_BINARY_DIR) / "grader" / "grade-config.json");
  edit(cfg);
  std::ofstream(dir / "grade-config.json") << cfg.dump(1);
  return dir / "grade-config.json";
}

// The ids of this build's assignments (grade-config.json, sorted as the grader lists them), with
// `extra` among them: "a1, a2, zz". The build may link A1 alone or A1 with others.
std::string build_ids(const std::string& extra = "") {
  std::vector<std::string> ids;
  const Json cfg = read_json(fs::path(JELLY_BINARY_DIR) / "grader" / "grade-config.json");
  for (const auto& item : cfg["assignments"].items()) ids.push_back(item.key());
  if (!extra.empty()) ids.push_back(extra);
  std::sort(ids.begin(), ids.end());
  std::string out;
  for (const std::string& id : ids) out += (out.empty() ? "" : ", ") + id;
  return out;
}

fs::path two_assignments() {
  return config_with("two", [](Json& cfg) {
    const fs::path zz = kWork / "configs" / "zz-assignments" / "zz";
    fs::create_directories(zz);
    std::ofstream(zz / "assignment.toml")
        << "id = \"zz\"\nnamespace = \"zz\"\ntitle = \"Another\"\nfiles = [\"thing.cpp\", "
           "\"other.cpp\"]\n[grading]\nautograded_total = 10.0\n[[task]]\nid = \"ZZ.T1\"\n"
           "title = \"Thing\"\nfile = \"thing.cpp\"\npoints = 10\n";
    Json a = cfg["assignments"]["a1"];
    a["dir"] = zz.string();
    a["solutions_dir"] = (zz / "no-solutions").string();
    a["reference_runner"] = "";
    cfg["assignments"]["zz"] = a;
  });
}

}  // namespace

// An unknown id is a usage error naming the ones the build has.
TEST(GraderAssignment, UnknownIdNamesTheKnownOnesAndExitsTwo) {
  const Cmd one = run("grade " + submission("unknown-id").string() + " --assignment a9 --out " +
                      (kWork / "out" / "unknown-id").string());
  EXPECT_EQ(one.status, 2) << one.out;
  EXPECT_NE(one.out.find(
                "--assignment a9: no such assignment in this build (it has: " + build_ids() + ")"),
            std::string::npos)
      << one.out;
  EXPECT_FALSE(fs::exists(kWork / "out" / "unknown-id" / "results.json"));
  const Cmd two = run("gradescope-zip " + (kWork / "unknown.zip").string() +
                      " --assignment A1 --config " + two_assignments().string());
  EXPECT_EQ(two.status, 2) << two.out;
  EXPECT_NE(two.out.find("--assignment A1: no such assignment in this build (it has: " +
                         build_ids("zz") + ")"),
            std::string::npos)
      << two.out;
}

// A draft (draft = true in its manifest: built, not graded without --draft) is not in
// "assignments"; the build names it in "drafts" so that --assignment of it says why, not only that
// it is unknown, and how its author grades it all the same. This build's own config lists its
// drafts (none, or the tree's) and, in "draft_assignments", those that have a grader.
TEST(GraderAssignment, ADraftIsNamedAsOneAndNotGraded) {
  const Json built = read_json(fs::path(JELLY_BINARY_DIR) / "grader" / "grade-config.json");
  ASSERT_TRUE(built.contains("drafts") && built["drafts"].is_array())
      << built.dump(1).substr(0, 400);
  ASSERT_TRUE(built.contains("draft_assignments") && built["draft_assignments"].is_object())
      << built.dump(1).substr(0, 400);
  for (const auto& item : built["draft_assignments"].items()) {
    EXPECT_FALSE(built["assignments"].contains(item.key())) << item.key();
    EXPECT_NE(std::find(built["drafts"].begin(), built["drafts"].end(), item.key()),
              built["drafts"].end())
        << item.key();
  }
  const fs::path cfg = config_with("draft", [](Json& c) { c["drafts"] = Json::array({"zz"}); });
  const fs::path out = kWork / "out" / "draft";
  const Cmd r = run("grade " + submission("draft").string() + " --assignment zz --config " +
                    cfg.string() + " --out " + out.string());
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(
      r.out.find("--assignment zz: zz is a draft in this build (its assignment.toml says "
                 "draft = true): it is built but not graded until that line is gone; its author "
                 "tries its grader with --draft (it has: " +
                 build_ids() + ")"),
      std::string::npos)
      << r.out;
  EXPECT_FALSE(fs::exists(out / "results.json"));
  // --draft of a draft without a grader yet, of an assignment that is no draft, and without
  // --assignment: each says what it is.
  const Cmd none =
      run("grade " + submission("draft").string() + " --assignment zz --draft --config " +
          cfg.string() + " --out " + out.string());
  EXPECT_EQ(none.status, 2) << none.out;
  EXPECT_NE(none.out.find("--assignment zz --draft: zz is a draft without a grader yet"),
            std::string::npos)
      << none.out;
  const Cmd a1 =
      run("grade " + submission("draft").string() + " --assignment a1 --draft --config " +
          cfg.string() + " --out " + out.string());
  EXPECT_EQ(a1.status, 2) << a1.out;
  EXPECT_NE(a1.out.find("--assignment a1 --draft: a1 is not a draft in this build (it has: " +
                        build_ids() + ")"),
            std::string::npos)
      << a1.out;
  const Cmd bare = run("generate-reference --draft --config " + cfg.string());
  EXPECT_EQ(bare.status, 2) << bare.out;
  EXPECT_NE(bare.out.find("--draft: say which draft with --assignment ID"), std::string::npos)
      << bare.out;
  EXPECT_FALSE(fs::exists(out / "results.json"));
}

// Its author grades a draft that has a grader on request: A1's entry made a draft of a copy of
// this build's config ("draft_assignments") is refused without --draft and graded with it, full
// marks for its reference.
TEST(GraderAssignment, ADraftIsGradedOnRequest) {
  const Json built = read_json(fs::path(JELLY_BINARY_DIR) / "grader" / "grade-config.json");
  if (built["assignments"].size() < 2) GTEST_SKIP() << "this build links A1 alone";
  const fs::path cfg = config_with("draft-a1", [](Json& c) {
    c["drafts"] = Json::array({"a1"});
    c["draft_assignments"] = Json::object({{"a1", c["assignments"]["a1"]}});
    c["assignments"].erase("a1");
  });
  const fs::path out = kWork / "out" / "draft-a1";
  fs::remove_all(out);
  const Cmd refused = run("grade " + submission("draft-a1").string() +
                          " --assignment a1 --config " + cfg.string() + " --out " + out.string());
  EXPECT_EQ(refused.status, 2) << refused.out;
  EXPECT_NE(refused.out.find("its author tries its grader with --draft"), std::string::npos)
      << refused.out;
  EXPECT_FALSE(fs::exists(out / "results.json"));
  const Json r =
      grade(submission("draft-a1"), "draft-a1", "--assignment a1 --draft --config " + cfg.string());
  EXPECT_DOUBLE_EQ(r["score"].get<double>(), 80.0);
}

// With two assignments and no --assignment, a submission's files choose: A1's five files (in a
// nested folder, beside a README) are graded as a1, with full marks; files of neither are an
// error that says how to choose.
TEST(GraderAssignment, InferredFromTheSubmissionsFiles) {
  const fs::path two = two_assignments();
  const Json r = grade(submission("inferred"), "inferred", "--config " + two.string());
  EXPECT_DOUBLE_EQ(r["score"].get<double>(), 80.0);
  EXPECT_NE(find_test(r, "a1.t4.spring_force.values"), nullptr);
  const fs::path neither = kWork / "submissions" / "neither";
  fs::remove_all(neither);
  fs::create_directories(neither);
  std::ofstream(neither / "main.cpp") << "int main() {}\n";
  const Cmd n = run("grade " + neither.string() + " --config " + two.string() + " --out " +
                    (kWork / "out" / "neither").string());
  EXPECT_EQ(n.status, 2) << n.out;
  EXPECT_NE(n.out.find("its files do not name exactly one assignment; say which with "
                       "--assignment ID (this build has: " +
                       build_ids("zz") + ")"),
            std::string::npos)
      << n.out;
  // A command without a submission cannot infer: it asks.
  const Cmd zip =
      run("gradescope-zip " + (kWork / "two.zip").string() + " --config " + two.string());
  EXPECT_EQ(zip.status, 2) << zip.out;
  EXPECT_NE(zip.out.find("this build has several assignments (" + build_ids("zz") +
                         "): say which with --assignment ID"),
            std::string::npos)
      << zip.out;
}

// A config written before assignments were plug-ins, and a manifest with a mistake: errors that
// name the file and the key (exit 2, nothing graded).
TEST(GraderAssignment, ConfigWithoutAssignmentsAndBadManifestsAreClearErrors) {
  const fs::path old = config_with("old", [](Json& cfg) { cfg.erase("assignments"); });
  const Cmd r = run("grade " + submission("old-config").string() + " --config " + old.string() +
                    " --out " + (kWork / "out" / "old-config").string());
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find(old.string() + ": assignments: expected an object with one entry per "
                                      "assignment (rebuild: this config predates assignments as "
                                      "plug-ins)"),
            std::string::npos)
      << r.out;

  // A copy of a1's manifest with a typo in the fourth task's handout key.
  const fs::path a1 = kWork / "configs" / "bad-manifest" / "a1";
  fs::remove_all(a1.parent_path());
  fs::create_directories(a1);
  std::string text = read_text(kSource / "assignments" / "a1" / "assignment.toml");
  const auto task4 = text.find("id = \"A1.T4\"");
  ASSERT_NE(task4, std::string::npos);
  const auto key = text.find("handout = ", task4);
  text.replace(key, 7, "handuot");
  const long line = 1 + std::count(text.begin(), text.begin() + key, '\n');
  std::ofstream(a1 / "assignment.toml") << text;
  const fs::path bad =
      config_with("bad", [&](Json& cfg) { cfg["assignments"]["a1"]["dir"] = a1.string(); });
  const Cmd b = run("grade " + submission("bad-manifest").string() + " --config " + bad.string() +
                    " --out " + (kWork / "out" / "bad-manifest").string());
  EXPECT_EQ(b.status, 2) << b.out;
  EXPECT_NE(b.out.find((a1 / "assignment.toml").string() + ":" + std::to_string(line) +
                       ": task[4].handuot: expected no such key"),
            std::string::npos)
      << b.out;
  EXPECT_FALSE(fs::exists(kWork / "out" / "bad-manifest" / "results.json"));
}

// A rubric whose points no longer add up to autograded_total scales every task: the grader says
// what each task is now worth (one task raised from 5 to 10 moves every other one).
TEST(GraderAssignment, AScaledRubricStatesEveryTasksNewPoints) {
  std::string text = read_text(kSource / "assignments" / "a1" / "assignment.toml");
  const auto task1 = text.find("id = \"A1.T1\"");
  ASSERT_NE(task1, std::string::npos);
  const auto key = text.find("points = 5\n", task1);
  ASSERT_NE(key, std::string::npos);
  text.replace(key, 10, "points = 10");
  const fs::path rubric = kWork / "configs" / "rubric-t1-10.toml";
  fs::create_directories(rubric.parent_path());
  std::ofstream(rubric) << text;
  const fs::path out = kWork / "out" / "rubric-t1-10";
  const Cmd r = run("grade " + submission("rubric-t1-10").string() + " --assignment a1 --rubric " +
                    rubric.string() + " --out " + out.string() + " --format gradescope");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("the tasks' points add up to 85.00, not autograded_total = 80.00"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("A1.T1 9.41 (written 10.00)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("A1.T2 4.71 (written 5.00)"), std::string::npos) << r.out;
  // The manifest as it is adds up: nothing is said.
  const Cmd plain = run("grade " + submission("rubric-plain").string() + " --assignment a1 --out " +
                        (kWork / "out" / "rubric-plain").string() + " --format gradescope");
  EXPECT_EQ(plain.out.find("add up to"), std::string::npos) << plain.out;
}

// A rubric change reaches the grader at once, but Gradescope only with a new zip and the students'
// self-check only with a new release: once the manifest differs from the one the last zip of this
// build tree was built from, every command says so in one line on standard error (and nothing
// before any zip, or while the manifest is the zip's). One zip: it takes a while.
TEST(GraderAssignment, AManifestChangedAfterTheGradescopeZipIsSaid) {
  const fs::path root = kWork / "zip-record";
  fs::remove_all(root);
  fs::create_directories(root);
  const fs::path a1 = root / "a1";
  fs::copy(kSource / "assignments" / "a1", a1, fs::copy_options::recursive);
  const fs::path config = config_with("zip-record", [&](Json& cfg) {
    cfg["binary_dir"] = (root / "build").string();
    cfg["assignments"]["a1"]["dir"] = a1.string();
  });
  // A command that fails after the notice would be printed (no such submission): seconds.
  const std::string probe = "grade " + (root / "no-submission").string() +
                            " --assignment a1 --config " + config.string() + " --out " +
                            (root / "out").string();
  const std::string notice = "changed after the Gradescope zip";
  EXPECT_EQ(run(probe).out.find(notice), std::string::npos) << "no zip was built here yet";
  const fs::path zip = root / "a1.zip";
  const std::string make_zip =
      "gradescope-zip " + zip.string() + " --assignment a1 --config " + config.string();
  const Cmd made = run(make_zip);
  ASSERT_EQ(made.status, 0) << made.out;
  EXPECT_EQ(run(probe).out.find(notice), std::string::npos) << "the zip's own manifest";

  std::string text = read_text(a1 / "assignment.toml");
  const auto key = text.find("autograded_total = 80.0");
  ASSERT_NE(key, std::string::npos);
  text.replace(key, 23, "autograded_total = 81.0");
  std::ofstream(a1 / "assignment.toml", std::ios::binary) << text;
  const Cmd after = run(probe);
  const std::string line =
      "jelly-grade: " + (a1 / "assignment.toml").string() + " changed after the Gradescope zip " +
      zip.string() +
      " was built: this grader uses the new manifest now, but Gradescope grades with the zip you "
      "uploaded (build and upload a new one: jelly-grade gradescope-zip OUT.zip --assignment a1) "
      "and students self-check with the release they have (publish a new one: "
      "tools/make-student-release)\n";
  EXPECT_NE(after.out.find(line), std::string::npos) << after.out;

  // The manifest as the zip has it again: nothing to say.
  std::ofstream(a1 / "assignment.toml", std::ios::binary)
      << read_text(kSource / "assignments" / "a1" / "assignment.toml");
  EXPECT_EQ(run(probe).out.find(notice), std::string::npos) << "the zip's manifest again";
}

// The instructor guide's example case (§2, "Add or hide a test"), pasted as it is at the end of a
// copy of A1's forces.toml, is a new case that generate-reference writes ("wrote (new)"); the same
// block with a mistyped parameter key fails naming the key and the case's file:line. A copy of the
// tree's grader/runner and assignments/a1 (with forces.toml and tolerances.toml only, for time)
// stands in for the checkout, so that nothing is written into it.
TEST(GraderGuide, ExampleCasePastesAndGenerates) {
  const std::string guide = read_text(kSource / "docs" / "instructor-guide.md");
  const auto section = guide.find("## 2. Add or hide a test");
  ASSERT_NE(section, std::string::npos);
  const auto fence = guide.find("```toml\n[[case]]\n", section);
  ASSERT_NE(fence, std::string::npos) << "the guide's example case block";
  const auto begin = fence + 8;
  const std::string block = guide.substr(begin, guide.find("```", begin) - begin);
  const auto id_at = block.find("id = \"") + 6;
  const std::string id = block.substr(id_at, block.find('"', id_at) - id_at);

  const fs::path root = kWork / "guide-case";
  fs::remove_all(root);
  const fs::path src = root / "src", a1 = src / "assignments" / "a1";
  fs::create_directories(src / "grader" / "data" / "a1" / "hidden");
  fs::create_directories(a1.parent_path());
  fs::copy(kSource / "grader" / "runner", src / "grader" / "runner", fs::copy_options::recursive);
  fs::copy(kSource / "assignments" / "a1", a1, fs::copy_options::recursive);
  for (const auto& e : fs::directory_iterator(a1 / "grader" / "cases")) {
    const std::string name = e.path().filename().string();
    EXPECT_EQ(read_text(e.path()).find("id = \"" + id + "\""), std::string::npos)
        << "the guide's example must be a new case, but " << name << " has " << id;
    if (name != "forces.toml" && name != "tolerances.toml") fs::remove(e.path());
  }
  const fs::path forces = a1 / "grader" / "cases" / "forces.toml";
  const std::string original = read_text(forces);
  std::ofstream(forces, std::ios::app) << "\n" << block;
  const fs::path config = config_with("guide-case", [&](Json& cfg) {
    cfg["source_dir"] = src.string();
    cfg["binary_dir"] = (root / "build").string();
    cfg["assignments"]["a1"]["dir"] = a1.string();
  });
  const std::string generate = "generate-reference --assignment a1 --config " + config.string();
  const Cmd made = run(generate);
  ASSERT_EQ(made.status, 0) << made.out;
  EXPECT_NE(made.out.find("  wrote (new) " + id + ".json\n"), std::string::npos) << made.out;
  EXPECT_TRUE(fs::exists(src / "grader" / "data" / "a1" / "hidden" / (id + ".json")));

  // A mistyped key: the runner names it, the grader adds where the case is.
  std::string typo = block;
  const auto seed = typo.find("seed = ");
  ASSERT_NE(seed, std::string::npos) << "the example's parameters have a seed";
  typo.replace(seed, 4, "sede");
  std::ofstream(forces, std::ios::binary) << original << "\n" << typo;
  const auto line = std::count(original.begin(), original.end(), '\n') + 2;  // its [[case]]
  const Cmd bad = run(generate);
  EXPECT_EQ(bad.status, 2) << bad.out;
  const auto said = bad.out.find(forces.string() + ":" + std::to_string(line) + ": case " + id);
  EXPECT_NE(said, std::string::npos) << bad.out;
  EXPECT_NE(bad.out.find("params.random.seed is missing", said), std::string::npos) << bad.out;
}

// --rubric: a manifest-shaped file with the term's own points replaces the manifest's.
TEST(GraderAssignment, RubricOptionTakesAManifestShapedFile) {
  std::string text = read_text(kSource / "assignments" / "a1" / "assignment.toml");
  const std::string total = "autograded_total = 80.0";
  ASSERT_NE(text.find(total), std::string::npos);
  text.replace(text.find(total), total.size(), "autograded_total = 40.0");
  const fs::path rubric = kWork / "configs" / "rubric-40.toml";
  fs::create_directories(rubric.parent_path());
  std::ofstream(rubric) << text;
  const Json r = grade(submission("rubric-40"), "rubric-40", "--rubric " + rubric.string());
  EXPECT_NEAR(r["score"].get<double>(), 40.0, 1e-6);
  EXPECT_NEAR(task_score(r, "A1.T13"), 15.0 / 2.0, 1e-4) << "points scaled to the new total";
}
