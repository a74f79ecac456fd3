// A3's grading of a forward kinematics that never returns or returns NaN (issue 31: "a student's
// FK that loops or returns NaN: a failed test with a message, never a crashed grader"): one
// submission, the reference with a forward_kinematics that loops on the course's 31-bone skeleton
// and returns NaN ends on every other. Its tests fail with the grader's messages, and every other
// task keeps its points. Graded without a sandbox (--isolation none: the sandboxes are the
// red-team suite's), public tests only.
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "shell_quote.hpp"

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

const fs::path kSource = JELLY_SOURCE_DIR;
const fs::path kWork = fs::path(JELLY_BINARY_DIR) / "tests-grader" / "a3";
// An assignment's reference as a submission: every file of its `files`, from solutions/<id>/ or
// from a task module, in the folder the build makes (build/assignments/<id>/reference/).
fs::path reference_dir(const std::string& id) {
  return fs::path(JELLY_BINARY_DIR) / "assignments" / id / "reference";
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Replaces the one occurrence of `find` in `text` (a failure when it is not there).
std::string replaced(std::string text, const std::string& find, const std::string& with) {
  const auto at = text.find(find);
  EXPECT_NE(at, std::string::npos)
      << "the reference kinematics.cpp (solutions/tasks/kinematics/) no longer has: " << find;
  if (at != std::string::npos) text.replace(at, find.size(), with);
  return text;
}

const Json* test_named(const Json& results, const std::string& id) {
  for (const Json& t : results["tests"])
    if (t["name"].get<std::string>().find("[" + id + "]") != std::string::npos) return &t;
  return nullptr;
}

double task_score(const Json& results, const std::string& task) {
  double s = 0.0;
  for (const Json& t : results["tests"])
    if (t["name"].get<std::string>().rfind(task + " ", 0) == 0) s += t["score"].get<double>();
  return s;
}

TEST(GraderA3, ALoopingOrNanForwardKinematicsFailsItsTestsWithAMessage) {
  const fs::path sub = kWork / "fk-loop-nan";
  fs::remove_all(sub);
  fs::create_directories(sub);
  for (const char* f : {"time_warp.cpp", "blend.cpp"})
    fs::copy_file(reference_dir("a3") / f, sub / f);
  std::string fk = read_text(reference_dir("a3") / "kinematics.cpp");
  fk = replaced(fk, "  if (skeleton.bones.empty()) return;\n",
                "  if (skeleton.bones.empty()) return;\n"
                "  for (volatile int spin = 0; n == 31; spin = spin + 1) {\n  }\n");
  fk = replaced(fk, "  out.end[i] = out.start[i] + bone.L * along;",
                "  out.end[i] = out.start[i] + bone.L * along / (bone.L - bone.L);");
  std::ofstream(sub / "kinematics.cpp") << fk;

  const fs::path out = kWork / "fk-loop-nan-out";
  fs::remove_all(out);
  const std::string cmd = jelly::testing::shell_quoted(JELLY_GRADE_EXE) + " grade " +
                          jelly::testing::shell_quoted(sub.string()) +
                          " --assignment a3 --isolation none --visibility public --timeout 3"
                          " --no-frames --format gradescope --out " +
                          jelly::testing::shell_quoted(out.string()) + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  std::string said;
  char buf[4096];
  for (std::size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) said.append(buf, n);
  const int status = pclose(p);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << said;
  const Json r = Json::parse(read_text(out / "results.json"));

  const Json* loop = test_named(r, "a3.t2.fk.course_ik");
  ASSERT_NE(loop, nullptr) << r.dump(1);
  EXPECT_EQ((*loop)["status"], "failed");
  EXPECT_NE((*loop)["output"].get<std::string>().find("took longer than 3 s"), std::string::npos)
      << (*loop)["output"];
  EXPECT_NE((*loop)["output"].get<std::string>().find("forward_kinematics"), std::string::npos)
      << (*loop)["output"];
  const Json* nan = test_named(r, "a3.t2.fk.random");
  ASSERT_NE(nan, nullptr) << r.dump(1);
  EXPECT_EQ((*nan)["status"], "failed");
  EXPECT_NE((*nan)["output"].get<std::string>().find("NaN or infinity (not a number)"),
            std::string::npos)
      << (*nan)["output"];

  EXPECT_EQ(task_score(r, "A3.T2"), 0.0);
  for (const char* task : {"A3.T1", "A3.T3", "A3.T4", "A3.B1"})
    EXPECT_GT(task_score(r, task), 0.0) << task << " lost its points";
}

}  // namespace
