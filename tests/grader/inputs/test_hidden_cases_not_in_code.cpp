// The grader's runner code (grader/runner/, shipped in the student release so that students can
// run the public tests), the body kinds' slot-level cases (framework/bodies/<kind>/grader/) and
// each assignment's case generators (assignments/<id>/grader/runner/)
// must not say what the hidden tests feed the student's code: a hidden case is a generator name
// plus parameters in assignments/<id>/grader/cases/*.toml, and the release tool drops hidden
// [[case]] entries. For every assignment of the build (grade-config.json), this test builds the
// list of hidden case ids and hidden parameter values from its case files and fails when any of
// them appears in the runner code of any assignment or of the general harness (outside a runner's
// hidden/ folder, which the release leaves out). It also proves that the scan finds a hidden case
// written back into code the way the runner once registered them.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <toml++/toml.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

const fs::path kSource = JELLY_SOURCE_DIR;

// Every assignment of the build: id -> its folder (grade-config.json's "assignments").
std::map<std::string, fs::path> assignments() {
  std::ifstream in(fs::path(JELLY_BINARY_DIR) / "grader" / "grade-config.json");
  EXPECT_TRUE(in) << "no grade-config.json: build jelly-grade";
  std::map<std::string, fs::path> out;
  if (!in) return out;
  const nlohmann::json j = nlohmann::json::parse(in);
  for (const auto& [id, a] : j.at("assignments").items()) out[id] = a.at("dir").get<std::string>();
  EXPECT_FALSE(out.empty());
  return out;
}

// The runner code shipped to students: the general harness, the body kinds' slot-level cases and
// every assignment's generators.
std::vector<fs::path> runner_folders() {
  std::vector<fs::path> out = {kSource / "grader" / "runner"};
  for (const auto& kind : fs::directory_iterator(kSource / "framework" / "bodies"))
    if (fs::is_directory(kind.path() / "grader")) out.push_back(kind.path() / "grader");
  for (const auto& [id, dir] : assignments()) out.push_back(dir / "grader" / "runner");
  return out;
}

// Parameter values of one visibility, flattened.
struct Values {
  std::set<std::string> ids;
  std::set<std::string> strings;             // string leaves
  std::set<double> numbers;                  // |value| of numeric leaves
  std::set<std::vector<double>> vectors;     // arrays of exactly 3 numbers
  std::map<std::string, std::string> where;  // value text → "case id: params.key" (for messages)
};

void collect(const toml::node& n, const std::string& path, Values& v) {
  if (const toml::table* t = n.as_table()) {
    for (const auto& [k, c] : *t) collect(c, path + "." + std::string(k.str()), v);
  } else if (const toml::array* a = n.as_array()) {
    if (a->size() == 3 &&
        std::all_of(a->begin(), a->end(), [](const toml::node& e) { return e.is_number(); })) {
      std::vector<double> vec;
      for (const toml::node& e : *a) vec.push_back(e.value<double>().value());
      v.vectors.insert(vec);
    }
    for (std::size_t i = 0; i < a->size(); ++i)
      collect(*a->get(i), path + "[" + std::to_string(i) + "]", v);
  } else if (auto s = n.value_exact<std::string>()) {
    v.strings.insert(*s);
    v.where.emplace(*s, path);
  } else if (auto d = n.value<double>()) {
    v.numbers.insert(std::abs(*d));
  }
}

struct CaseValues {
  Values hidden, pub;
};

CaseValues case_values(const fs::path& cases_dir) {
  CaseValues out;
  for (const auto& e : fs::directory_iterator(cases_dir)) {
    if (e.path().extension() != ".toml") continue;
    const toml::table tbl = toml::parse_file(e.path().string());
    const toml::array* cases = tbl["case"].as_array();
    if (!cases) continue;
    for (const toml::node& n : *cases) {
      const toml::table& c = *n.as_table();
      const std::string id = c["id"].value_or(std::string());
      Values& v =
          c["visibility"].value_or(std::string("public")) == "hidden" ? out.hidden : out.pub;
      v.ids.insert(id);
      if (const toml::node* p = c.get("params")) collect(*p, id + ": params", v);
    }
  }
  return out;
}

// What a code file must not contain, given the hidden and public values.
struct Needles {
  std::set<std::string> texts;            // hidden ids and distinctive hidden strings
  std::set<double> numbers;               // distinctive hidden numbers (as |value|)
  std::set<long> seeds;                   // hidden random seeds
  std::set<std::vector<double>> vectors;  // hidden 3-vectors no public case uses
};

// Integers below 100 (loop bounds, buffer sizes, bit shifts), numbers that a public case also uses
// and grid directions (vectors of −1, 0, 1: the spring offsets) are not evidence of a hidden case;
// everything else the hidden cases use is.
Needles needles(const CaseValues& cv) {
  Needles n;
  for (const std::string& id : cv.hidden.ids) n.texts.insert(id);
  static const std::regex keyword("^[a-z_]+$");  // option names (mode = "drop") are generator code
  for (const std::string& s : cv.hidden.strings)
    if (!cv.pub.strings.count(s) && s.size() >= 6 && !std::regex_match(s, keyword))
      n.texts.insert(s);
  for (double d : cv.hidden.numbers) {
    const bool small_integer = d == std::floor(d) && d < 100.0;
    if (!small_integer && !cv.pub.numbers.count(d)) n.numbers.insert(d);
  }
  for (const auto& v : cv.hidden.vectors) {
    const bool grid =
        std::all_of(v.begin(), v.end(), [](double c) { return c == 0.0 || std::abs(c) == 1.0; });
    if (!grid && !cv.pub.vectors.count(v)) n.vectors.insert(v);
  }
  return n;
}

// Every hidden seed, from params.seed and params.*.seed anywhere in hidden cases.
std::set<long> hidden_seeds(const fs::path& cases_dir) {
  std::set<long> seeds;
  std::function<void(const toml::node&, bool)> walk = [&](const toml::node& n, bool hidden) {
    if (const toml::table* t = n.as_table())
      for (const auto& [k, c] : *t) {
        if (hidden && k.str() == "seed" && c.is_integer()) seeds.insert(*c.value<long>());
        walk(c, hidden);
      }
  };
  for (const auto& e : fs::directory_iterator(cases_dir)) {
    if (e.path().extension() != ".toml") continue;
    const toml::table tbl = toml::parse_file(e.path().string());
    if (const toml::array* cases = tbl["case"].as_array())
      for (const toml::node& n : *cases)
        if (const toml::node* p = n.as_table()->get("params"))
          walk(*p, (*n.as_table())["visibility"].value_or(std::string()) == "hidden");
  }
  return seeds;
}

const char* kNumber = R"((?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)";

bool same(double a, double b) {
  return a == b || std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b));
}

// Every leak in one file's text: "what (line N)".
std::vector<std::string> leaks_in(const std::string& text, const Needles& n) {
  std::vector<std::string> out;
  auto line_of = [&](std::size_t pos) {
    return std::to_string(1 + std::count(text.begin(), text.begin() + pos, '\n'));
  };
  for (const std::string& t : n.texts) {
    const auto at = text.find(t);
    if (at != std::string::npos)
      out.push_back("hidden text \"" + t + "\" (line " + line_of(at) + ")");
  }
  // Numeric literals: not inside identifiers, not the hex of a constant.
  static const std::regex literal(std::string(R"((^|[^\w.])()") + kNumber + R"()(?![\w.]))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), literal);
       it != std::sregex_iterator(); ++it) {
    const double v = std::stod((*it)[2].str());
    for (double d : n.numbers)
      if (same(v, d))
        out.push_back("hidden number " + (*it)[2].str() + " (line " + line_of(it->position(2)) +
                      ")");
  }
  // Three literals in a row: a hidden vector (a hole centre, a rotation axis, ...).
  static const std::regex triple(std::string("(-?)\\s*(") + kNumber + ")\\s*,\\s*(-?)\\s*(" +
                                 kNumber + ")\\s*,\\s*(-?)\\s*(" + kNumber + ")");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), triple);
       it != std::sregex_iterator(); ++it) {
    std::vector<double> v;
    for (int k = 0; k < 3; ++k)
      v.push_back(((*it)[1 + 2 * k].length() ? -1.0 : 1.0) * std::stod((*it)[2 + 2 * k].str()));
    for (const auto& h : n.vectors)
      if (same(v[0], h[0]) && same(v[1], h[1]) && same(v[2], h[2]))
        out.push_back("hidden vector (" + it->str() + ") (line " + line_of(it->position()) + ")");
  }
  // Seeds: integer literals inside a Sequence construction.
  static const std::regex sequence(R"(Sequence\s+\w+\s*[({]([^;]*)[)}])");
  static const std::regex integer(R"((^|[^\w.])(\d+)(?![\w.]))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), sequence);
       it != std::sregex_iterator(); ++it) {
    const std::string args = (*it)[1].str();
    for (auto jt = std::sregex_iterator(args.begin(), args.end(), integer);
         jt != std::sregex_iterator(); ++jt)
      if (n.seeds.count(std::stol((*jt)[2].str())))
        out.push_back("hidden seed " + (*jt)[2].str() + " in \"" + it->str() + "\" (line " +
                      line_of(it->position()) + ")");
  }
  return out;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(GraderCases, HiddenCasesExistAndLiveInTheCaseFiles) {
  for (const auto& [id, dir] : assignments()) {
    SCOPED_TRACE(id);
    const CaseValues cv = case_values(dir / "grader" / "cases");
    EXPECT_GE(cv.hidden.ids.size(), 20u)
        << "the scan below would prove nothing without hidden cases";
    const Needles n = needles(cv);
    EXPECT_FALSE(n.numbers.empty());
    EXPECT_FALSE(n.vectors.empty());
    EXPECT_FALSE(hidden_seeds(dir / "grader" / "cases").empty());
  }
}

TEST(GraderCases, NoHiddenCaseIdOrParameterInTheRunnerCode) {
  for (const auto& [id, dir] : assignments()) {
    SCOPED_TRACE(id);
    const CaseValues cv = case_values(dir / "grader" / "cases");
    Needles n = needles(cv);
    n.seeds = hidden_seeds(dir / "grader" / "cases");
    int files = 0;
    std::string report;
    for (const fs::path& folder : runner_folders())
      for (const auto& e : fs::recursive_directory_iterator(folder)) {
        if (!e.is_regular_file()) continue;
        const fs::path rel = fs::relative(e.path(), folder);
        if (*rel.begin() == "hidden") continue;  // never released
        ++files;
        for (const std::string& leak : leaks_in(read(e.path()), n))
          report += "  " + fs::relative(e.path(), kSource).string() + ": " + leak + "\n";
      }
    EXPECT_GE(files, 10);
    EXPECT_TRUE(report.empty()) << "the runner code (shipped to students) says what " << id
                                << "'s hidden tests feed "
                                << "their code;\nmove these into the hidden case's params in " << id
                                << "'s grader/cases/*.toml:\n"
                                << report;
  }
}

// The scan is not blind: the way hidden cases used to be registered in code is reported.
TEST(GraderCases, TheScanFindsAHiddenCaseWrittenBackIntoCode) {
  const fs::path cases = assignments().at("a1") / "grader" / "cases";
  const CaseValues cv = case_values(cases);
  Needles n = needles(cv);
  n.seeds = hidden_seeds(cases);
  const std::string old_code = R"(
    r.add({"a1.t4.spring_force.random", "spring_force on 12 random springs", nullptr,
           [](const TaskTable& t, const Json&, Outputs& o) { run_springs(t, random_inputs(41, 12), o); }});
    Sequence r(bowl ? 11 : 13);
    p.hole_center = Vec3(1.0, -2.0, 0.0);
    const int steps = collision ? 1500 : 1000;
    Terrain t = *terrain_preset("course-2021-tilted");)";
  const std::vector<std::string> found = leaks_in(old_code, n);
  std::string all;
  for (const std::string& f : found) all += f + "\n";
  for (const char* expected : {"a1.t4.spring_force.random", "hidden seed 11", "hidden seed 13",
                               "hidden vector (1.0, -2.0, 0.0)", "hidden number 1500"})
    EXPECT_NE(all.find(expected), std::string::npos) << "not found: " << expected << "\nfound:\n"
                                                     << all;
  // The tilted plane's preset is public now (a1.t6.collide_plane.incline): naming it is no leak.
  EXPECT_EQ(all.find("course-2021-tilted"), std::string::npos) << all;
  // Generator code that reads its parameters is clean.
  EXPECT_TRUE(leaks_in("Sequence r(static_cast<std::uint64_t>(params.integer(\"seed\")));\n"
                       "const long steps = params.integer(\"steps\");",
                       n)
                  .empty());
}
