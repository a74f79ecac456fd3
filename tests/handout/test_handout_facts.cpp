// Every number the handout quotes is a fact this test recomputes from the code (issue 12): spring
// counts from the reference builders, free-fall heights and orders of convergence by simulating,
// stability limits by running the detector, points from assignments/a1/assignment.toml, the course
// scene's coefficients from the framework. In assignments/a1/handout/*.md a quoted number carries a
// tag right after it, invisible in the rendered page:
//
//     y = 9.775<!-- fact: rk4.com_y_after_0.5s -->
//
// (the number may end a `code span` or **bold** text just before the tag). The test fails when a
// tag names an unknown fact, when the number before a tag disagrees with the code (to the digits
// the text gives), when a fact is never quoted, and when a "Check yourself" section or the points
// table quotes an untagged quantity (the rule is in docs/instructor-guide.md §4a).
//
// Stability facts run the course scene for 10 s per quoted step (a minute in all): they are checked
// only in the slow build of this file (JELLY_HANDOUT_SLOW, label slow); the fast build checks that
// they are tagged and known.
#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "a1_manifest.hpp"
#include "jelly/a1/task_table.hpp"
#include "jelly/cube.hpp"
#include "jelly/simulator.hpp"
#include "scenes_in_code.hpp"

#ifndef JELLY_HANDOUT_SLOW
#define JELLY_HANDOUT_SLOW 0
#endif

namespace fs = std::filesystem;

namespace jelly {
namespace {

const fs::path kSource = JELLY_SOURCE_DIR;

// A fact checks the number the text quotes: "" when it holds, else what the code says.
struct Fact {
  bool slow = false;
  std::function<std::string(double quoted, int decimals)> check;
};

std::string show(double v) {
  std::ostringstream o;
  o.precision(10);
  o << v;
  return o.str();
}

// The quoted number is the code's value rounded to the digits the text gives.
Fact value(std::function<double()> f) {
  return {false, [f](double quoted, int decimals) {
            const double v = f();
            const double half_ulp = 0.5 * std::pow(10.0, -decimals) * (1 + 1e-9);
            return std::abs(v - quoted) <= half_ulp ? std::string() : "the code gives " + show(v);
          }};
}

// "≈ N": the observed order of convergence within 0.3 of the quoted one.
Fact order(IntegratorKind kind) {
  return {false, [kind](double quoted, int) {
            const double observed = std::log2(testing::error_at_one_second(kind, 2.5e-3) /
                                              testing::error_at_one_second(kind, 1.25e-3));
            return std::abs(observed - quoted) <= 0.3 ? std::string()
                                                      : "the observed order is " + show(observed);
          }};
}

// The course scene with this integrator at the quoted step for 10 s: stable (or not).
Fact stability(IntegratorKind kind, bool stable) {
  return {
      true, [kind, stable](double h, int) {
        Simulator sim(build_world(testing::course_2023(kind, h), a1::task_table()), {kind, h});
        const bool ok = sim.run_until(10.0) == StepResult::Ok;
        if (ok == stable) return std::string();
        return std::string(to_string(kind)) + " at h = " + show(h) +
               (ok ? " ran 10 s without blowing up" : " blew up at t = " + show(sim.time()) + " s");
      }};
}

// Centre of mass height of the course cube after t seconds (course scene, h = 0.001).
double com_y_after(IntegratorKind kind, double t) {
  Simulator sim(build_world(testing::course_2023(kind), a1::task_table()), {kind, 0.001});
  sim.run_until(t);
  return sim.state().x.row(1).mean();
}

std::size_t spring_count(void (*TaskTable::*builder)(const CubeLattice&, std::vector<Spring>&),
                         int n) {
  CubeSpec spec = course_2023_scene().cube;
  spec.n = n;
  const CubeLattice cube(spec, 0);
  std::vector<Spring> springs;
  (a1::task_table().*builder)(cube, springs);
  return springs.size();
}

// Shear springs of the course cube whose grid offset has three non-zero components (body
// diagonals).
std::size_t body_diagonals(int n) {
  CubeSpec spec = course_2023_scene().cube;
  spec.n = n;
  const CubeLattice cube(spec, 0);
  std::vector<Spring> springs;
  a1::task_table().add_shear_springs(cube, springs);
  std::size_t count = 0;
  for (const Spring& s : springs) {
    const int a = s.a, b = s.b;
    const bool di = a / (n * n) != b / (n * n), dj = (a / n) % n != (b / n) % n,
               dk = a % n != b % n;
    count += di && dj && dk;
  }
  return count;
}

// The rubric's points, scaled to autograded_total as the grader does.
struct Rubric {
  double total = 0, raw = 0;
  std::map<std::string, double> task, category;
};

Rubric rubric() {
  const AssignmentManifest& m = testing::a1_manifest();
  Rubric r;
  r.total = m.autograded_total;
  for (const ManifestTask& task : m.tasks) r.raw += task.points;
  for (const ManifestTask& task : m.tasks) {
    const double p = task.points * r.total / r.raw;
    r.task[task.id] = p;
    r.category[task.category] += p;
  }
  return r;
}

// RK4's stability interval on the negative real axis: the largest x with |R(−x)| ≤ 1.
double rk4_real_interval() {
  auto r = [](double z) {
    return std::abs(1 + z + z * z / 2 + z * z * z / 6 + z * z * z * z / 24);
  };
  double lo = 2.0, hi = 3.0;  // |R(−2)| < 1 < |R(−3)|
  for (int i = 0; i < 60; ++i) (r(-(lo + hi) / 2) <= 1 ? lo : hi) = (lo + hi) / 2;
  return lo;
}

const Plane& course_floor() {
  static const Terrain t = *terrain_preset("course-2023-floor");
  return std::get<Plane>(t.shape);
}
const Bowl& course_bowl() {
  static const Terrain t = *terrain_preset("course-2023-bowl");
  return std::get<Bowl>(t.shape);
}

std::map<std::string, Fact> facts() {
  using K = IntegratorKind;
  std::map<std::string, Fact> f;
  const auto n10 = [](auto builder) {
    return [builder] { return double(spring_count(builder, 10)); };
  };
  f["springs.structural.n10"] = value(n10(&TaskTable::add_structural_springs));
  f["springs.structural_both_ways.n10"] =
      value([] { return 2.0 * spring_count(&TaskTable::add_structural_springs, 10); });
  f["springs.shear.n10"] = value(n10(&TaskTable::add_shear_springs));
  f["springs.shear_face.n10"] = value(
      [] { return double(spring_count(&TaskTable::add_shear_springs, 10) - body_diagonals(10)); });
  f["springs.shear_body.n10"] = value([] { return double(body_diagonals(10)); });
  f["springs.bending.n10"] = value(n10(&TaskTable::add_bending_springs));
  f["springs.all.n10"] = value([] {
    return double(spring_count(&TaskTable::add_structural_springs, 10) +
                  spring_count(&TaskTable::add_shear_springs, 10) +
                  spring_count(&TaskTable::add_bending_springs, 10));
  });
  f["course.n"] = value([] { return double(course_2023_scene().cube.n); });
  f["course.dt"] = value([] { return course_2023_scene().dt; });
  f["course.center_x"] = value([] { return course_2023_scene().cube.center.x(); });
  f["course.center_y"] = value([] { return course_2023_scene().cube.center.y(); });
  f["course.kd"] = value([] { return course_2023_scene().structural.kd; });
  f["course.floor.epsilon"] = value([] { return course_floor().surface.epsilon; });
  f["course.floor.restitution"] = value([] { return course_floor().surface.restitution; });
  f["course.floor.friction"] = value([] { return course_floor().surface.friction; });
  f["course.bowl.radius"] = value([] { return course_bowl().radius; });
  f["course.bowl.rim_height"] = value([] { return course_bowl().rim_height; });
  f["freefall.seconds"] = value([] { return 0.5; });    // the time the com_y_after_0.5s facts use
  f["stability.seconds"] = value([] { return 10.0; });  // the run length of the stability facts
  for (const auto& [name, kind] : std::map<std::string, K>{{"explicit_euler", K::ExplicitEuler},
                                                           {"implicit_euler", K::ImplicitEuler},
                                                           {"midpoint", K::Midpoint},
                                                           {"rk4", K::RK4}}) {
    const K k = kind;
    f[name + ".com_y_after_0.5s"] = value([k] { return com_y_after(k, 0.5); });
    f[name + ".order"] = order(k);
    if (k == K::Midpoint) continue;  // the handout quotes no stability limit for midpoint
    f[name + ".stable_h"] = stability(k, true);
    f[name + ".unstable_h"] = stability(k, false);
  }
  // h|λ| of the course cube's stiffest damped mode at h = 0.001 (the course's implicit Euler is
  // stable up to h|λ| = 1), and when the detector stops the course scene at that step.
  f["implicit_euler.h_lambda_at_0.001"] = value([] {
    auto world = build_world(testing::course_2023(), a1::task_table());
    return 0.001 / estimate_stability(*world, world->state()).critical_step(K::ImplicitEuler);
  });
  f["implicit_euler.blowup_t_at_0.001"] = {
      true, [](double quoted, int decimals) {
        Simulator sim(build_world(testing::course_2023(K::ImplicitEuler), a1::task_table()),
                      {K::ImplicitEuler, 0.001});
        if (sim.run_until(10.0) == StepResult::Ok)
          return std::string("it ran 10 s without blowing up");
        return value([&] { return sim.time(); }).check(quoted, decimals);
      }};
  f["rk4.real_interval"] = value([] { return -rk4_real_interval(); });
  f["points.autograded"] = value([] { return rubric().total; });
  f["points.report"] = value([] { return 100.0 - rubric().total; });
  for (const char* c : {"springs", "forces", "collision", "integrators"})
    f[std::string("points.") + c] = value([c = std::string(c)] { return rubric().category.at(c); });
  for (int t = 1; t <= 13; ++t) {
    const std::string id = "A1.T" + std::to_string(t);
    f["points." + id] = value([id] { return rubric().task.at(id); });
  }
  f["points.A1.T11+T12"] =
      value([] { return rubric().task.at("A1.T11") + rubric().task.at("A1.T12"); });
  return f;
}

struct Tag {
  std::string file, fact, number;
  int line = 0;
};

std::vector<std::string> lines_of(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

std::vector<fs::path> handout_pages() {
  std::vector<fs::path> pages;
  for (const auto& e : fs::directory_iterator(kSource / "assignments" / "a1" / "handout"))
    if (e.path().extension() == ".md") pages.push_back(e.path());
  std::sort(pages.begin(), pages.end());
  return pages;
}

const std::regex kTag(R"(<!-- fact: ([A-Za-z0-9_.+]+) -->)");
// The number right before a tag (a Unicode or ASCII minus, digits, decimals), maybe closing a
// code span or bold text.
const std::regex kNumberBeforeTag("((?:\xE2\x88\x92|-)?[0-9]+(?:\\.[0-9]+)?)(?:`|\\*\\*)?$");

std::vector<Tag> tags() {
  std::vector<Tag> out;
  for (const fs::path& page : handout_pages()) {
    const std::vector<std::string> lines = lines_of(page);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const std::string& l = lines[i];
      for (auto it = std::sregex_iterator(l.begin(), l.end(), kTag); it != std::sregex_iterator();
           ++it) {
        Tag t{page.filename().string(), (*it)[1].str(), "", static_cast<int>(i + 1)};
        std::smatch m;
        const std::string before = l.substr(0, static_cast<std::size_t>(it->position()));
        if (std::regex_search(before, m, kNumberBeforeTag)) t.number = m[1].str();
        out.push_back(t);
      }
    }
  }
  return out;
}

double parse_number(std::string s, int& decimals) {
  if (s.rfind("\xE2\x88\x92", 0) == 0) s = "-" + s.substr(3);
  const auto dot = s.find('.');
  decimals = dot == std::string::npos ? 0 : static_cast<int>(s.size() - dot - 1);
  return std::stod(s);
}

TEST(HandoutFacts, EveryTaggedNumberIsWhatTheCodeComputes) {
  const std::map<std::string, Fact> known = facts();
  std::set<std::string> used;
  const std::vector<Tag> all = tags();
  ASSERT_FALSE(all.empty()) << "no <!-- fact: ... --> tags in assignments/a1/handout/";
  for (const Tag& t : all) {
    const std::string where = t.file + ":" + std::to_string(t.line) + ": fact " + t.fact;
    const auto f = known.find(t.fact);
    if (f == known.end()) {
      ADD_FAILURE() << where << ": no such fact (tests/handout/test_handout_facts.cpp lists them)";
      continue;
    }
    used.insert(t.fact);
    if (t.number.empty()) {
      ADD_FAILURE() << where << ": no number right before the tag";
      continue;
    }
    if (f->second.slow && !JELLY_HANDOUT_SLOW) continue;
    int decimals = 0;
    const double quoted = parse_number(t.number, decimals);
    const std::string why = f->second.check(quoted, decimals);
    EXPECT_TRUE(why.empty()) << where << ": the text says " << t.number << ", but " << why;
  }
  for (const auto& [name, fact] : known)
    EXPECT_TRUE(used.count(name))
        << "fact " << name
        << " is quoted nowhere in assignments/a1/handout/: remove it or quote it";
}

// A quantity a student would rely on: a number with a decimal point, a number of 10 or more, or a
// number after "≈" or "about", outside `code`, not part of a name (A1.T4, T1–T3, course-2023,
// 2×2×2). Such a number in a "Check yourself" section or in the points table must carry a tag.
std::vector<std::string> untagged_quantities(const std::string& line) {
  std::string l = std::regex_replace(line, std::regex("`[^`]*`"), " ");
  l = std::regex_replace(
      l, std::regex("(?:\xE2\x88\x92|-)?[0-9.]+(?:`|\\*\\*)?<!-- fact: [^>]*-->"), " ");
  l = std::regex_replace(l, std::regex("\\]\\([^)]*\\)"), "]");  // link targets
  std::vector<std::string> out;
  const std::regex number(
      "(^|[^A-Za-z0-9_.\xC3\x97\\-])([0-9]+(?:\\.[0-9]+)?)(?![A-Za-z0-9_\xC3\x97])");
  for (auto it = std::sregex_iterator(l.begin(), l.end(), number); it != std::sregex_iterator();
       ++it) {
    const std::string n = (*it)[2].str();
    const std::string before = l.substr(0, static_cast<std::size_t>(it->position(2)));
    const bool approx = std::regex_search(before, std::regex("(\xE2\x89\x88|about) *$"));
    if (n.find('.') != std::string::npos || std::stod(n) >= 10 || approx) out.push_back(n);
  }
  return out;
}

TEST(HandoutFacts, CheckYourselfSectionsAndThePointsTableQuoteOnlyTaggedNumbers) {
  for (const fs::path& page : handout_pages()) {
    const std::vector<std::string> lines = lines_of(page);
    bool in_check = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const std::string& l = lines[i];
      if (l.rfind("## ", 0) == 0)
        in_check = l == "## Check yourself" || l == "## 3. Check yourself";
      const bool points_row = l.rfind("| [A1.T", 0) == 0 || l.rfind("| [Report]", 0) == 0;
      if (!in_check && !points_row) continue;
      for (const std::string& n : untagged_quantities(l))
        ADD_FAILURE() << page.filename().string() << ":" << i + 1 << ": the number " << n
                      << " has no <!-- fact: ... --> tag (docs/instructor-guide.md §4a): " << l;
    }
  }
}

TEST(HandoutFacts, TheUntaggedNumberRuleFindsQuantitiesAndSparesNames) {
  EXPECT_EQ(untagged_quantities("blows up at about h = 0.0025."),
            std::vector<std::string>{"0.0025"});
  EXPECT_EQ(untagged_quantities("the order of convergence (≈ 4)."), std::vector<std::string>{"4"});
  EXPECT_EQ(untagged_quantities("12876 springs"), std::vector<std::string>{"12876"});
  EXPECT_TRUE(
      untagged_quantities("y = 9.775<!-- fact: rk4.com_y_after_0.5s --> and `--dt 0.002`").empty());
  EXPECT_TRUE(
      untagged_quantities("A1.T4, T1–T3, course-2023.toml, 2×2×2 and 4×4×4 cubes, kd = 0").empty());
}

}  // namespace
}  // namespace jelly
