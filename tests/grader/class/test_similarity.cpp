// `jelly-grade similarity` (grader/src/class/similarity.hpp) on a synthetic class: a copy of the
// reference with its identifiers renamed, its indentation changed and its comments replaced is
// found; an independent correct solution (tests/grader/class/similarity/independent/) and a
// submission of the bare stubs are not; hostile names and text reach the page escaped. Needs
// sim_c++ (Debian package similarity-tester, installed by tools/install-deps.sh): without it these
// tests fail, saying so.
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "shell_quote.hpp"

namespace fs = std::filesystem;
using Json = nlohmann::json;

// The folder "<img src=x onerror=alert(1)>" gets this id: ids are made safe as folder names
// (submissions.cpp), before any report sees them.
constexpr const char* kHostileId = "_img src=x onerror=alert(1)_";

namespace {

const fs::path kSource = JELLY_SOURCE_DIR;
const fs::path kWork = fs::path(JELLY_BINARY_DIR) / "tests-grader" / "similarity";
// An assignment's reference as a submission: every file of its `files`, from solutions/<id>/ or
// from a task module, in the folder the build makes (build/assignments/<id>/reference/).
fs::path reference_dir(const std::string& id) {
  return fs::path(JELLY_BINARY_DIR) / "assignments" / id / "reference";
}
const char* const kTaskFiles[] = {"springs.cpp", "forces.cpp", "collision.cpp", "contact.cpp",
                                  "integrators.cpp"};

struct Cmd {
  int status = -1;
  std::string out;
};

// `env` (e.g. "PATH=/x") before jelly-grade, then its arguments; stdout and stderr together.
Cmd run(const std::string& args, const std::string& env = "") {
  const std::string cmd = env + (env.empty() ? "" : " ") +
                          jelly::testing::shell_quoted(JELLY_GRADE_EXE) + " " + args + " 2>&1";
  Cmd r;
  FILE* p = popen(cmd.c_str(), "r");
  char buf[4096];
  std::size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
  const int st = pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

std::string q(const fs::path& p) { return jelly::testing::shell_quoted(p.string()); }

// The reference's file as a student who copied it would hand it in: every identifier the file
// declares renamed, indented by 4 instead of 2, its comments dropped and others added elsewhere.
std::string disguised(const std::string& text) {
  static const std::pair<const char*, const char*> kRenames[] = {
      {"length", "len"},
      {"rest", "natural"},
      {"d", "delta"},
      {"u", "dir"},
      {"n", "nrm"},
      {"phi", "depth"},
      {"vn", "v_perp"},
      {"vt", "v_par"},
      {"offsets", "steps"},
      {"o", "off"},
      {"i2", "ii"},
      {"j2", "jj"},
      {"k2", "kk"},
      {"out", "springs"},
      {"cube", "grid"},
      {"to_center", "c"},
      {"distance", "dist"},
      {"in_plane", "lat"},
      {"a0", "acc0"},
      {"a1", "acc1"},
      {"predicted", "guess"},
      {"mid", "half"},
      {"nf", "dn"},
      {"fc", "f_norm"},
      {"ff", "f_fric"},
      {"eps", "tol"},
      {"reflect", "bounce"},
      {"push_back", "react"},
      {"add_forward_springs", "link_all"}};
  std::string s = text;
  for (const auto& [from, to] : kRenames)
    s = std::regex_replace(s, std::regex(std::string("\\b") + from + "\\b"), to);
  std::istringstream in(s);
  std::string line, result = "// Assignment 1, my solution\n";
  int n = 0;
  while (std::getline(in, line)) {
    if (const std::size_t c = line.find("//"); c != std::string::npos) line.erase(c);
    std::size_t indent = line.find_first_not_of(' ');
    if (indent == std::string::npos) indent = line.size();
    line = std::string(indent * 2, ' ') + line.substr(indent);
    while (!line.empty() && line.back() == ' ') line.pop_back();
    result += line + "\n";
    if (++n % 7 == 0) result += "\n    // step " + std::to_string(n) + "\n";
  }
  return result;
}

// The synthetic class under `root`: reference, a disguised copy (one file under a Canvas name, one
// nested), an independent solution of T1–T5, the bare stubs, and a copy under a hostile name with
// hostile text in it.
void make_class(const fs::path& root) {
  fs::remove_all(root);
  const fs::path ref = reference_dir("a1");
  for (const char* f : kTaskFiles) {
    write(root / "ref" / f, read(ref / f));
    const std::string name = std::string(f) == "forces.cpp" ? "copy_LATE_12345_67890_forces-1.cpp"
                             : std::string(f) == "contact.cpp" ? std::string("src/") + f
                                                               : std::string(f);
    write(root / "copy" / name, disguised(read(ref / f)));
    write(root / "stubs" / f, read(kSource / "assignments" / "a1" / f));
    // The independent student solved T1–T5 (springs.cpp, forces.cpp); the rest are the stubs.
    const bool solved = std::string(f) == "springs.cpp" || std::string(f) == "forces.cpp";
    write(root / "indep" / f,
          read(solved ? kSource / "tests" / "grader" / "class" / "similarity" / "independent" / f
                      : kSource / "assignments" / "a1" / f));
    // The hostile text mid-file, in a comment: the shared region runs across it (sim_c++ skips
    // comments), so the page shows it.
    std::string text = read(ref / f);
    std::size_t mid = text.size() / 2;
    mid = text.find('\n', mid) + 1;
    text.insert(mid, "// </pre><script>alert(1)</script>\x1b[31m\x01 red\n");
    write(root / "<img src=x onerror=alert(1)>" / f, text);
  }
}

bool has_sim() { return std::system("command -v sim_c++ >/dev/null 2>&1") == 0; }
constexpr const char* kNoSim =
    "sim_c++ is not installed: install the Debian package similarity-tester "
    "(sudo tools/install-deps.sh installs it)";

const Json* find_pair(const Json& pairs, const std::string& a, const std::string& b) {
  for (const Json& p : pairs)
    if ((p["a"] == a && p["b"] == b) || (p["a"] == b && p["b"] == a)) return &p;
  return nullptr;
}

TEST(Similarity, DisguisedCopyIsFoundIndependentSolutionIsNot) {
  ASSERT_TRUE(has_sim()) << kNoSim;
  const fs::path cls = kWork / "class", out = kWork / "out";
  make_class(cls);
  fs::remove_all(out);
  const Cmd r = run("similarity " + q(cls) + " --out " + q(out) + " --assignment a1");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("not a verdict"), std::string::npos) << r.out;
  const Json j = Json::parse(read(out / "similarity.json"));
  SCOPED_TRACE(j.dump(1).substr(0, 4000));
  EXPECT_EQ(j["submissions"], 5);
  EXPECT_EQ(j["pairs_compared"], 10);
  const Json& pairs = j["pairs"];
  // The disguised copy: nearly all of both sides' own lines are in shared regions.
  const Json* copy = find_pair(pairs, "ref", "copy");
  ASSERT_NE(copy, nullptr) << "the disguised copy of the reference was not flagged";
  EXPECT_GE(copy->at("percent_a").get<double>(), 90.0);
  EXPECT_GE(copy->at("percent_b").get<double>(), 90.0);
  // Its regions name both sides' files as submitted (the Canvas name, the nested folder), with
  // line ranges.
  bool lms = false, nested = false;
  for (const Json& region : copy->at("regions")) {
    const std::string copy_file = copy->at("a") == "copy" ? region["a_file"] : region["b_file"];
    lms = lms || copy_file == "copy_LATE_12345_67890_forces-1.cpp";
    nested = nested || copy_file == "src/contact.cpp";
    EXPECT_LE(region["a_lines"][0].get<int>(), region["a_lines"][1].get<int>());
    EXPECT_GT(region["tokens"].get<int>(), 0);
  }
  EXPECT_TRUE(lms && nested);
  // The hostile-named copy of the reference is found too (it is one).
  EXPECT_NE(find_pair(pairs, "ref", kHostileId), nullptr);
  // Neither the independent solution nor the bare stubs pair with anyone.
  for (const Json& p : pairs)
    for (const char* who : {"indep", "stubs"})
      EXPECT_TRUE(p["a"] != who && p["b"] != who) << who << " flagged: " << p.dump();
  // How far below the threshold the independent solution stays (the margin is in docs/grader.md).
  for (const Json& p : j["highest_below_threshold"])
    if (p["a"] == "indep" || p["b"] == "indep")
      std::cout << "independent pair: " << p.dump() << "\n";
  // The stubs submission is listed as not compared, file by file.
  int stub_notes = 0;
  for (const Json& n : j["not_compared"])
    stub_notes += n.get<std::string>().rfind("stubs: ", 0) == 0;
  EXPECT_EQ(stub_notes, 5);

  const std::string html = read(out / "similarity.html");
  EXPECT_NE(html.find("Evidence, not a verdict."), std::string::npos);
  EXPECT_EQ(html.find("<script>"), std::string::npos);
  EXPECT_EQ(html.find("<img"), std::string::npos);
  EXPECT_EQ(html.find('\x1b'), std::string::npos);
  EXPECT_NE(html.find("&lt;/pre&gt;&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
  EXPECT_NE(html.find(kHostileId), std::string::npos);
  EXPECT_NE(html.find("copy_LATE_12345_67890_forces-1.cpp lines "), std::string::npos);
  EXPECT_FALSE(fs::exists(out / "similarity-work"));
}

TEST(Similarity, ThresholdSelectsPairs) {
  ASSERT_TRUE(has_sim()) << kNoSim;
  const fs::path cls = kWork / "class-threshold", out = kWork / "out-threshold";
  make_class(cls);
  fs::remove_all(out);
  // At 100 % only the hostile copy (the reference plus one comment line) and the reference remain
  // certain; the disguised copy may keep a line outside its regions.
  const Cmd r = run("similarity " + q(cls) + " --out " + q(out) + " --threshold 100");
  ASSERT_EQ(r.status, 0) << r.out;
  const Json j = Json::parse(read(out / "similarity.json"));
  EXPECT_NE(find_pair(j["pairs"], "ref", kHostileId), nullptr) << j.dump(1);
  for (const Json& p : j["pairs"]) {
    EXPECT_GE(std::max(p["percent_a"].get<double>(), p["percent_b"].get<double>()), 99.95);
  }
}

TEST(Similarity, ClearErrors) {
  const fs::path cls = kWork / "class-errors", out = kWork / "out-errors";
  make_class(cls);
  fs::remove_all(out);
  // No sim_c++ on PATH: exit status 2 naming the package.
  const fs::path empty = kWork / "empty-path";
  fs::create_directories(empty);
  Cmd r = run("similarity " + q(cls) + " --out " + q(out), "PATH=" + q(empty));
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("similarity-tester"), std::string::npos) << r.out;
  // batch --similarity says so before it grades anyone.
  r = run("batch " + q(cls) + " --out " + q(out) + " --similarity", "PATH=" + q(empty));
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("similarity-tester"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out / "scores.csv"));
  // A threshold that is no percentage, and --threshold on batch without --similarity.
  r = run("similarity " + q(cls) + " --out " + q(out) + " --threshold 0");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("percentage"), std::string::npos) << r.out;
  r = run("batch " + q(cls) + " --out " + q(out) + " --threshold 40");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("--similarity"), std::string::npos) << r.out;
  // One submission is nothing to compare.
  const fs::path one = kWork / "class-one";
  fs::remove_all(one);
  write(one / "ref" / "forces.cpp", read(reference_dir("a1") / "forces.cpp"));
  r = run("similarity " + q(one) + " --out " + q(out) + " --assignment a1");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("at least two"), std::string::npos) << r.out;
}

// A task file that is a symbolic or hard link (to the reference, say), or too large, is not read:
// listed as not compared, never shown, never paired.
TEST(Similarity, LinksAndHugeFilesAreNotRead) {
  ASSERT_TRUE(has_sim()) << kNoSim;
  const fs::path cls = kWork / "class-links", out = kWork / "out-links";
  fs::remove_all(cls);
  fs::remove_all(out);
  const fs::path ref = reference_dir("a1");
  for (const char* f : kTaskFiles) write(cls / "ref" / f, read(ref / f));
  fs::create_directories(cls / "linker");
  fs::create_symlink(ref / "springs.cpp", cls / "linker" / "springs.cpp");
  fs::create_hard_link(cls / "ref" / "forces.cpp", cls / "linker" / "forces.cpp");
  write(cls / "linker" / "collision.cpp", std::string((1u << 20) + 1, ';'));
  const Cmd r = run("similarity " + q(cls) + " --out " + q(out) + " --assignment a1");
  ASSERT_EQ(r.status, 0) << r.out;
  const Json j = Json::parse(read(out / "similarity.json"));
  EXPECT_TRUE(j["pairs"].empty()) << j.dump(1);
  std::string notes;
  for (const Json& n : j["not_compared"]) notes += n.get<std::string>() + "\n";
  EXPECT_NE(notes.find("linker: springs.cpp (springs.cpp) is a symbolic link"), std::string::npos)
      << notes;
  EXPECT_NE(notes.find("forces.cpp (forces.cpp) is a hard link"), std::string::npos) << notes;
  EXPECT_NE(notes.find("linker: collision.cpp (collision.cpp) is larger than 1024 KiB"),
            std::string::npos)
      << notes;
}

// Code the handout gives (a ```cpp block of a handout page) does not count, as the stub's does not:
// two submissions that are the reference's forces.cpp are flagged, and not once the handout holds
// that code. The handout is changed in a copy of assignments/a1/ that a copy of grade-config.json
// names.
TEST(Similarity, HandoutCodeDoesNotCount) {
  ASSERT_TRUE(has_sim()) << kNoSim;
  const fs::path cls = kWork / "class-handout", a1 = kWork / "handout-copy" / "a1";
  fs::remove_all(cls);
  fs::remove_all(a1);
  fs::create_directories(a1.parent_path());
  const std::string forces = read(reference_dir("a1") / "forces.cpp");
  for (const char* who : {"alice", "bob"}) write(cls / who / "forces.cpp", forces);
  fs::copy(kSource / "assignments" / "a1", a1, fs::copy_options::recursive);
  Json config = Json::parse(read(fs::path(JELLY_BINARY_DIR) / "grader" / "grade-config.json"));
  config["assignments"]["a1"]["dir"] = a1.string();
  write(kWork / "grade-config-handout.json", config.dump(1));
  const auto flagged = [&](const std::string& name) {
    const fs::path out = kWork / ("out-handout-" + name);
    const Cmd r = run("similarity " + q(cls) + " --out " + q(out) + " --assignment a1 --config " +
                      q(kWork / "grade-config-handout.json"));
    if (r.status != 0) ADD_FAILURE() << r.out;
    return r.status == 0 ? Json::parse(read(out / "similarity.json"))["pairs"].size() : 99u;
  };
  EXPECT_EQ(flagged("before"), 1u);
  write(a1 / "handout" / "T4-spring-force.md",
        read(a1 / "handout" / "T4-spring-force.md") + "\n```cpp\n" + forces + "```\n");
  EXPECT_EQ(flagged("after"), 0u);
}

// The independent solution the first test relies on is a correct one: graded, every test of
// A1.T1–A1.T5 passes (its other task files are the stubs, whose tasks score 0).
TEST(Similarity, IndependentSolutionIsCorrect) {
  const fs::path sub = kWork / "independent", out = kWork / "out-independent";
  fs::remove_all(sub);
  fs::remove_all(out);
  for (const char* f : {"springs.cpp", "forces.cpp"})
    write(sub / f, read(kSource / "tests" / "grader" / "class" / "similarity" / "independent" / f));
  const Cmd r =
      run("grade " + q(sub) + " --assignment a1 --no-frames --format gradescope --out " + q(out));
  ASSERT_EQ(r.status, 0) << r.out;
  const Json j = Json::parse(read(out / "results.json"));
  int graded = 0;
  for (const Json& t : j["tests"]) {
    if (!t.contains("tags") || t["tags"].empty()) continue;
    const std::string task = t["tags"][0];
    if (task < "A1.T1" || task > "A1.T5" || task.size() != 5) continue;
    ++graded;
    EXPECT_EQ(t["status"], "passed") << t.dump();
  }
  EXPECT_GE(graded, 5);
}

// batch --similarity: the same report next to scores.csv. Two identical copies of the reference
// (their objects come from the grader's cache after the first).
TEST(Similarity, BatchWritesTheReportToo) {
  ASSERT_TRUE(has_sim()) << kNoSim;
  const fs::path cls = kWork / "class-batch", out = kWork / "out-batch";
  fs::remove_all(cls);
  fs::remove_all(out);
  for (const char* who : {"alice", "bob"})
    for (const char* f : kTaskFiles) write(cls / who / f, read(reference_dir("a1") / f));
  const Cmd r = run("batch " + q(cls) + " --out " + q(out) +
                    " --no-frames --visibility public --similarity --threshold 80");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(fs::exists(out / "scores.csv"));
  const Json j = Json::parse(read(out / "similarity.json"));
  EXPECT_EQ(j["threshold_percent"], 80.0);
  ASSERT_EQ(j["pairs"].size(), 1u) << j.dump(1);
  EXPECT_EQ(j["pairs"][0]["percent_a"], 100.0);
}

}  // namespace
