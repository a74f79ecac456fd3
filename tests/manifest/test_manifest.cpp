// The assignment manifest (framework/manifest, docs/new-assignment.md): every shipped manifest
// reads; a mistake is an error naming the file, the line, the key and what was expected; and the
// assignment a submission belongs to is inferred from its files only when they name exactly one.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "jelly/manifest.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kSource = JELLY_SOURCE_DIR;

// A small manifest that reads; each error test changes one line of it.
const std::string kGood = R"(id = "p1"
namespace = "p1"
title = "A projectile"
files = ["launch.cpp", "drag.cpp"]

[grading]
autograded_total = 10.0

[[task]]
id = "P1.T1"
title = "Launch"
file = "launch.cpp"
functions = ["launch"]
points = 4

[[task]]
id = "P1.T2"
title = "Drag"
file = "drag.cpp"
functions = ["drag_force"]
points = 6
)";

std::string replaced(const std::string& from, const std::string& to) {
  std::string s = kGood;
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

// The message of the ManifestError that parsing `text` throws ("" when it parses).
std::string error_of(const std::string& text) {
  try {
    jelly::parse_manifest(text, "assignments/p1/assignment.toml");
  } catch (const jelly::ManifestError& e) {
    return e.what();
  }
  return "";
}

jelly::AssignmentManifest with_files(const std::string& id, std::vector<std::string> files) {
  jelly::AssignmentManifest m;
  m.id = id;
  m.files = std::move(files);
  return m;
}

}  // namespace

TEST(Manifest, TheSmallManifestReadsWithItsTasksAndGrading) {
  const jelly::AssignmentManifest m = jelly::parse_manifest(kGood, "p1.toml");
  EXPECT_EQ(m.id, "p1");
  EXPECT_EQ(m.ns, "p1");
  EXPECT_EQ(m.files, (std::vector<std::string>{"launch.cpp", "drag.cpp"}));
  EXPECT_DOUBLE_EQ(m.autograded_total, 10.0);
  EXPECT_DOUBLE_EQ(m.hand_graded_points, 0.0) << "no hand-graded part unless the manifest says";
  EXPECT_EQ(m.hidden_visibility, "after_due_date");
  ASSERT_EQ(m.tasks.size(), 2u);
  EXPECT_EQ(m.tasks[1].id, "P1.T2");
  EXPECT_EQ(m.tasks[1].file, "drag.cpp");
  EXPECT_DOUBLE_EQ(m.tasks[1].points, 6.0);
  EXPECT_EQ(m.tasks[0].short_name, "Launch") << "short defaults to the title";
  EXPECT_EQ(m.task_prefix(), "P1.");
  EXPECT_EQ(m.find_task("P1.T1")->functions_text(), "launch (launch.cpp)");
  EXPECT_EQ(m.find_task("P1.T3"), nullptr);
}

// `hand_graded_points` says how many points are graded by hand, apart from autograded_total.
TEST(Manifest, HandGradedPointsAreRead) {
  const jelly::AssignmentManifest m = jelly::parse_manifest(
      replaced("autograded_total = 10.0", "autograded_total = 10.0\nhand_graded_points = 5"),
      "p1.toml");
  EXPECT_DOUBLE_EQ(m.autograded_total, 10.0);
  EXPECT_DOUBLE_EQ(m.hand_graded_points, 5.0);
}

// `contracts` names the contracts the grader's messages cite (the report's anchors); absent, none.
TEST(Manifest, ContractsAreReadAndMustBeAnchorNames) {
  EXPECT_TRUE(jelly::parse_manifest(kGood, "p1.toml").contracts.empty());
  const jelly::AssignmentManifest m = jelly::parse_manifest(
      replaced("files = [\"launch.cpp\", \"drag.cpp\"]",
               "files = [\"launch.cpp\", \"drag.cpp\"]\ncontracts = [\"ballistics\", \"drag-2\"]"),
      "p1.toml");
  EXPECT_EQ(m.contracts, (std::vector<std::string>{"ballistics", "drag-2"}));
  EXPECT_EQ(
      error_of(replaced("files = [\"launch.cpp\", \"drag.cpp\"]",
                        "files = [\"launch.cpp\", \"drag.cpp\"]\ncontracts = [\"Drag law\"]")),
      "assignments/p1/assignment.toml:5: contracts: expected names of lower-case letters, "
      "digits and '-' (a handout anchor), not \"Drag law\"");
}

// `bodies`: each entry a body kind, or kind:variant for only that variant of the kind's scenes;
// each scene claimed once.
TEST(Manifest, BodiesAreKindsOrKindsWithAVariant) {
  const std::string files = "files = [\"launch.cpp\", \"drag.cpp\"]";
  const auto with = [&](const std::string& bodies) {
    return replaced(files, files + "\nbodies = [" + bodies + "]");
  };
  EXPECT_TRUE(jelly::parse_manifest(kGood, "p1.toml").bodies.empty());
  const jelly::AssignmentManifest m =
      jelly::parse_manifest(with("\"point\", \"rope:braided\", \"rope:plain-2\""), "p1.toml");
  ASSERT_EQ(m.bodies.size(), 3u);
  EXPECT_EQ(m.bodies[0].kind, "point");
  EXPECT_EQ(m.bodies[0].variant, "");
  EXPECT_EQ(m.bodies[1].kind, "rope");
  EXPECT_EQ(m.bodies[1].variant, "braided");
  EXPECT_EQ(m.bodies[2].text(), "rope:plain-2");
  EXPECT_TRUE(m.claims("point", "") && m.claims("point", "any"));
  EXPECT_TRUE(m.claims("rope", "braided") && m.claims("rope", "plain-2"));
  EXPECT_FALSE(m.claims("rope", "knotted") || m.claims("rope", "") || m.claims("disc", ""));

  const std::string f = "assignments/p1/assignment.toml:5: bodies: expected ";
  const std::string form =
      "a body kind's name (a scene's [body] type: every scene of the kind) or kind:variant (only "
      "its scenes of that variant, docs/new-assignment.md), names of letters, digits, '_' and '-'";
  for (const char* bad : {"rope:", ":braided", "rope:braided:x", "rope braided", "rope:b/c"})
    EXPECT_EQ(error_of(with(std::string("\"point\", \"") + bad + "\"")),
              f + form + ", not \"" + bad + "\"")
        << bad;
  EXPECT_EQ(error_of(with("\"rope:plain\", \"rope\"")),
            f + "each scene claimed once, and \"rope:plain\" already claims the scenes \"rope\" "
                "does");
  EXPECT_EQ(error_of(with("\"rope:plain\", \"rope:plain\"")),
            f + "each scene claimed once, and \"rope:plain\" already claims the scenes "
                "\"rope:plain\" does");
  EXPECT_EQ(error_of(with("\"rope:plain\", \"rope:braided\", \"point\"")), "");
  EXPECT_EQ(error_of(with("\"rope\", 3")).rfind(f + "a list of the body.type names", 0), 0u);
}

// `bonus = true` marks a task whose points come on top of autograded_total; absent, false.
TEST(Manifest, ABonusTaskIsMarked) {
  const jelly::AssignmentManifest plain = jelly::parse_manifest(kGood, "p1.toml");
  EXPECT_FALSE(plain.tasks[0].bonus);
  EXPECT_FALSE(plain.tasks[1].bonus);
  const jelly::AssignmentManifest m =
      jelly::parse_manifest(replaced("points = 6", "points = 6\nbonus = true"), "p1.toml");
  EXPECT_FALSE(m.tasks[0].bonus);
  EXPECT_TRUE(m.tasks[1].bonus);
  EXPECT_DOUBLE_EQ(m.tasks[1].points, 6.0);
  EXPECT_EQ(error_of(replaced("points = 6", "points = 6\nbonus = false")), "");
}

// `draft = true` marks an assignment in preparation (built, never graded); absent it is false,
// and anything but a boolean is an error naming the key.
TEST(Manifest, ADraftIsMarked) {
  EXPECT_FALSE(jelly::parse_manifest(kGood, "p1.toml").draft);
  EXPECT_TRUE(
      jelly::parse_manifest(replaced("title = ", "draft = true\ntitle = "), "p1.toml").draft);
  EXPECT_NE(error_of(replaced("title = ", "draft = \"yes\"\ntitle = "))
                .find("draft: expected true or false"),
            std::string::npos)
      << error_of(replaced("title = ", "draft = \"yes\"\ntitle = "));
}

// Every assignment of the tree reads, from its folder, and its tasks' points and files agree.
TEST(Manifest, EveryShippedManifestReads) {
  const std::vector<jelly::AssignmentManifest> all =
      jelly::find_assignments(kSource / "assignments");
  ASSERT_FALSE(all.empty());
  for (const jelly::AssignmentManifest& m : all) {
    SCOPED_TRACE(m.id);
    EXPECT_EQ(m.dir.filename().string(), m.id);
    EXPECT_GT(m.autograded_total, 0.0);
    EXPECT_FALSE(m.tasks.empty());
    for (const std::string& f : m.files) EXPECT_TRUE(fs::exists(m.dir / f)) << f;
  }
  const auto a1 = std::find_if(all.begin(), all.end(),
                               [](const jelly::AssignmentManifest& m) { return m.id == "a1"; });
  ASSERT_NE(a1, all.end());
  EXPECT_EQ(a1->files, (std::vector<std::string>{"springs.cpp", "forces.cpp", "collision.cpp",
                                                 "contact.cpp", "integrators.cpp"}));
  EXPECT_DOUBLE_EQ(a1->autograded_total, 80.0);
  EXPECT_DOUBLE_EQ(a1->hand_graded_points, 20.0) << "A1's report: 80 + 20";
  double points = 0;
  for (const jelly::ManifestTask& t : a1->tasks) points += t.points;
  EXPECT_DOUBLE_EQ(points, 80.0) << "A1's raw points are the course's 2023 weights";
  for (const jelly::ManifestTask& t : a1->tasks) EXPECT_FALSE(t.bonus) << t.id;
  const auto a2 = std::find_if(all.begin(), all.end(),
                               [](const jelly::AssignmentManifest& m) { return m.id == "a2"; });
  if (a2 != all.end()) {
    // The course's 2024 weights: 80 autograded, friction's bonus on top.
    double regular = 0, bonus = 0;
    for (const jelly::ManifestTask& t : a2->tasks) (t.bonus ? bonus : regular) += t.points;
    EXPECT_DOUBLE_EQ(regular, 80.0);
    EXPECT_DOUBLE_EQ(bonus, 5.0);
    EXPECT_DOUBLE_EQ(a2->hand_graded_points, 20.0) << "A2's report: 80 + 20";
    ASSERT_NE(a2->find_task("A2.T12"), nullptr);
    EXPECT_TRUE(a2->find_task("A2.T12")->bonus);
  }
}

// Each mistake names file:line, the key and what was expected.
TEST(Manifest, ErrorsNameTheFileTheLineAndTheKey) {
  const std::string f = "assignments/p1/assignment.toml:";
  const struct {
    std::string text;
    std::string message;
  } cases[] = {
      // A typo in a task's key (line 13: "functoins").
      {replaced("functions = [\"launch\"]", "functoins = [\"launch\"]"),
       f + "13: task[1].functoins: expected no such key (see docs/new-assignment.md)"},
      // A typo in a required key: reported as the unknown key at its line, not as a missing one.
      {replaced("points = 4", "pionts = 4"),
       f + "14: task[1].pionts: expected no such key (see docs/new-assignment.md)"},
      // An unknown top-level key.
      {replaced("title = \"A projectile\"", "title = \"A projectile\"\nhandin = \"x\""),
       f + "4: handin: expected no such key"},
      // A task whose file is not one of `files`.
      {replaced("file = \"drag.cpp\"", "file = \"drags.cpp\""),
       f + "19: task[2].file: expected one of the assignment's `files`, not \"drags.cpp\""},
      // No [grading] table.
      {replaced("[grading]\nautograded_total = 10.0\n", ""),
       "assignments/p1/assignment.toml: grading: expected a [grading] table with autograded_total "
       "(the key is missing)"},
      // [grading] with its total misspelled: the unknown key, at its line.
      {replaced("autograded_total = 10.0", "total = 10.0"),
       f + "7: grading.total: expected no such key (see docs/new-assignment.md)"},
      // [grading] without its total.
      {replaced("autograded_total = 10.0\n", ""),
       "assignments/p1/assignment.toml: grading.autograded_total: expected a number of points ≥ 0 "
       "(the key is missing)"},
      {replaced("autograded_total = 10.0",
                "autograded_total = 10.0\nhidden_visibility = \"never\""),
       f + "8: grading.hidden_visibility: expected \"hidden\", \"after_due_date\" or "
           "\"after_published\", not \"never\""},
      {replaced("autograded_total = 10.0", "autograded_total = 10.0\nhand_graded_points = -20"),
       f + "8: grading.hand_graded_points: expected a number of points ≥ 0 graded by hand"},
      {replaced("points = 6", "points = -6"),
       f + "21: task[2].points: expected a number of points ≥ 0"},
      {replaced("id = \"P1.T2\"", "id = \"P1.T1\""),
       f + "17: task[2].id: expected a unique id (\"P1.T1\" is used twice)"},
      {replaced("files = [\"launch.cpp\", \"drag.cpp\"]",
                "files = [\"launch.cpp\", \"../drag.cpp\"]"),
       f + "4: files: expected plain file names in the assignment's folder, not \"../drag.cpp\""},
      {replaced("namespace = \"p1\"", "namespace = \"p-1\""),
       f + "2: namespace: expected a C++ identifier, not \"p-1\""},
      {replaced("id = \"p1\"\n", ""),
       "assignments/p1/assignment.toml: id: expected the assignment's "
       "id, a lower-case name such as \"hw1\" (the key is missing)"},
      {replaced("points = 4", "points = = 4"), f + "14: not valid TOML: "},
      // A non-ASCII character outside a string, where toml++ 3.3.0 would misread it.
      {replaced("points = 4", "points = 4é"), f + "14:11: malformed TOML: a non-ASCII character"},
      // A bonus flag that is not a boolean (line 22, after points).
      {replaced("points = 6", "points = 6\nbonus = \"yes\""),
       f + "22: task[2].bonus: expected true or false (true: its points come on top of "
           "grading.autograded_total)"},
      // A bonus worth nothing.
      {replaced("points = 6", "points = 0\nbonus = true"),
       f + "21: task[2].points: expected a number of points > 0 for a bonus task"},
      // Every task a bonus: nothing for autograded_total to be made of.
      {replaced("points = 6", "points = 6\nbonus = true")
           .replace(kGood.find("points = 4"), 10, "points = 4\nbonus = true"),
       f + "9: task: expected at least one task that is not a bonus with points > 0"},
  };
  for (const auto& c : cases) {
    const std::string e = error_of(c.text);
    EXPECT_EQ(e.rfind(c.message, 0), 0u) << "expected:\n  " << c.message << "\ngot:\n  " << e;
  }
  EXPECT_EQ(error_of(kGood), "");
}

// read_manifest: the id must be the folder's name (the CLI name and the folder are one).
TEST(Manifest, TheIdIsTheFoldersName) {
  const fs::path dir = fs::path(JELLY_BINARY_DIR) / "tests-manifest" / "p2";
  fs::create_directories(dir);
  std::ofstream(dir / "assignment.toml") << kGood;
  try {
    jelly::read_manifest(dir / "assignment.toml");
    ADD_FAILURE() << "a manifest with id p1 in folder p2 was read";
  } catch (const jelly::ManifestError& e) {
    EXPECT_NE(std::string(e.what()).find("assignment.toml: id: expected the folder's name \"p2\", "
                                         "not \"p1\""),
              std::string::npos)
        << e.what();
  }
  try {
    jelly::read_manifest(dir / "missing.toml");
    ADD_FAILURE() << "a missing manifest was read";
  } catch (const jelly::ManifestError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.toml: cannot read the assignment's manifest"),
              std::string::npos)
        << e.what();
  }
}

// A submission's files name its assignment when they name exactly one.
TEST(Manifest, TheAssignmentIsInferredFromASubmissionsFiles) {
  const std::vector<jelly::AssignmentManifest> all = {
      with_files("a1",
                 {"springs.cpp", "forces.cpp", "collision.cpp", "contact.cpp", "integrators.cpp"}),
      with_files("a2", {"cloth.cpp", "forces.cpp"}), with_files("p1", {"launch.cpp", "drag.cpp"})};
  auto id_for = [&](const std::vector<std::string>& present) {
    const jelly::AssignmentManifest* m = jelly::assignment_for_files(all, present);
    return m ? m->id : std::string("(none)");
  };
  // A1's five files, in any order, with other files beside them.
  EXPECT_EQ(id_for({"integrators.cpp", "contact.cpp", "collision.cpp", "forces.cpp", "springs.cpp",
                    "README.txt"}),
            "a1");
  EXPECT_EQ(id_for({"launch.cpp", "drag.cpp"}), "p1");
  // Some of one assignment's files and none of another's: that one (a partial submission).
  EXPECT_EQ(id_for({"drag.cpp"}), "p1");
  EXPECT_EQ(id_for({"springs.cpp", "README.txt"}), "a1");
  // forces.cpp alone is in a1 and a2: ambiguous. A2's complete set wins over a1's part of it.
  EXPECT_EQ(id_for({"forces.cpp"}), "(none)");
  EXPECT_EQ(id_for({"cloth.cpp", "forces.cpp"}), "a2");
  // Nothing known, or two complete sets.
  EXPECT_EQ(id_for({"README.txt"}), "(none)");
  EXPECT_EQ(id_for({}), "(none)");
  EXPECT_EQ(id_for({"launch.cpp", "drag.cpp", "cloth.cpp", "forces.cpp"}), "(none)");
  // The real a1 manifest.
  const std::vector<jelly::AssignmentManifest> tree =
      jelly::find_assignments(kSource / "assignments");
  const jelly::AssignmentManifest* a1 = jelly::assignment_for_files(
      tree, {"springs.cpp", "forces.cpp", "collision.cpp", "contact.cpp", "integrators.cpp"});
  ASSERT_NE(a1, nullptr);
  EXPECT_EQ(a1->id, "a1");
}
