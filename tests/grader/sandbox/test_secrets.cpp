// The sandbox's secret list (grader/src/sandbox/isolation.cpp, secrets_of, as choose_isolation
// hands it to every sandbox): every assignment's hidden data, cases, mutants, reference and
// reference runner, whichever assignment is graded. A submission of one assignment must not read
// another's. Checked on this build's grade-config.json, and on a copy of it with a second
// assignment beside a1 (a folder with its own manifest, solutions and reference runner): grading
// a1, the other's secrets are hidden too, and grading the other, a1's.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "inputs/config.hpp"
#include "sandbox/isolation.hpp"

namespace fs = std::filesystem;
using Json = nlohmann::json;
using jelly::grade::AssignmentConfig;
using jelly::grade::GradeConfig;

namespace {

const fs::path kConfig = fs::path(JELLY_BINARY_DIR) / "grader" / "grade-config.json";
const fs::path kWork = fs::path(JELLY_BINARY_DIR) / "tests-grader" / "secrets";

fs::path clean(const fs::path& p) { return fs::absolute(p).lexically_normal(); }

// Whether `p` is one of `secrets` or inside one.
bool covered(const std::vector<fs::path>& secrets, const fs::path& p) {
  const fs::path c = clean(p);
  for (const fs::path& s : secrets) {
    const fs::path rel = c.lexically_relative(clean(s));
    if (!rel.empty() && *rel.begin() != "..") return true;
  }
  return false;
}

std::string listed(const std::vector<fs::path>& secrets) {
  std::string out;
  for (const fs::path& s : secrets) out += "  " + s.string() + "\n";
  return out;
}

// The secrets a sandbox grading `id` hides, from the config at `path`.
std::vector<fs::path> secrets_grading(const std::string& path, const std::string& id) {
  GradeConfig config = jelly::grade::load_config(path);
  jelly::grade::select_assignment(config, id, {});
  return jelly::grade::choose_isolation(config, "none").secrets;
}

// What must be secret of one assignment.
std::vector<fs::path> secrets_of_assignment(const GradeConfig& config, const AssignmentConfig& a) {
  std::vector<fs::path> v = {config.source_dir / "grader" / "data" / a.id / "hidden",
                             a.dir / "grader" / "cases", a.dir / "grader" / "mutants",
                             a.solutions_dir, a.reference_dir};
  if (!a.reference_runner.empty()) v.push_back(a.reference_runner);
  return v;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(GraderSecrets, EveryAssignmentsHiddenDataCasesMutantsAndReferenceAreSecret) {
  const GradeConfig config = jelly::grade::load_config(kConfig.string());
  ASSERT_FALSE(config.assignments.empty());
  // A draft graded on request (grade-config.json's draft_assignments) keeps its secrets too.
  std::vector<AssignmentConfig> all = config.assignments;
  all.insert(all.end(), config.draft_assignments.begin(), config.draft_assignments.end());
  for (const AssignmentConfig& graded : config.assignments) {
    const std::vector<fs::path> secrets = secrets_grading(kConfig.string(), graded.id);
    for (const AssignmentConfig& a : all)
      for (const fs::path& p : secrets_of_assignment(config, a))
        EXPECT_TRUE(covered(secrets, p))
            << "grading " << graded.id << ": " << p << " of " << a.id << " is not secret:\n"
            << listed(secrets);
    // The public side stays visible: the stubs, headers and public data a submission builds with.
    EXPECT_FALSE(covered(secrets, graded.dir / "include")) << listed(secrets);
    EXPECT_FALSE(covered(secrets, graded.dir / "grader" / "data" / "public")) << listed(secrets);
  }
}

// With a second assignment in the build: each one's secrets are hidden while the other is graded.
TEST(GraderSecrets, ASubmissionOfOneAssignmentCannotReadAnothersSecrets) {
  fs::remove_all(kWork);
  const fs::path other = kWork / "assignments" / "zz";
  fs::create_directories(other / "grader" / "cases");
  fs::create_directories(other / "grader" / "mutants");
  fs::create_directories(kWork / "solutions" / "zz");
  std::ofstream(other / "assignment.toml")
      << "id = \"zz\"\nnamespace = \"zz\"\ntitle = \"Another\"\nfiles = [\"thing.cpp\"]\n"
         "[grading]\nautograded_total = 10.0\n"
         "[[task]]\nid = \"ZZ.T1\"\ntitle = \"Thing\"\nfile = \"thing.cpp\"\npoints = 10\n";
  Json cfg = Json::parse(read_text(kConfig));
  ASSERT_TRUE(cfg["assignments"].contains("a1"));
  const std::size_t linked = cfg["assignments"].size();  // A1 alone, or with others (A2)
  Json zz = cfg["assignments"]["a1"];
  zz["dir"] = other.string();
  zz["solutions_dir"] = (kWork / "solutions" / "zz").string();
  zz["reference_dir"] = (kWork / "reference" / "zz").string();
  zz["reference_runner"] = (kWork / "bin" / "jelly-grade-zz-reference-runner").string();
  cfg["assignments"]["zz"] = zz;
  const fs::path two = kWork / "grade-config.json";
  std::ofstream(two) << cfg.dump(1);

  const GradeConfig config = jelly::grade::load_config(two.string());
  ASSERT_EQ(config.assignments.size(), linked + 1);
  for (const char* graded : {"a1", "zz"}) {
    const std::vector<fs::path> secrets = secrets_grading(two.string(), graded);
    for (const AssignmentConfig& a : config.assignments)
      for (const fs::path& p : secrets_of_assignment(config, a))
        EXPECT_TRUE(covered(secrets, p))
            << "grading " << graded << ": " << p << " of " << a.id << " is not secret:\n"
            << listed(secrets);
  }
  // The check can fail: a path nobody declared secret is not covered.
  EXPECT_FALSE(covered(secrets_grading(two.string(), "a1"), other / "thing.cpp"));
}
