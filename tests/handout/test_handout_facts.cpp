// Every number the handout quotes is a fact this test recomputes from the code (issue 12, and issue
// 20 for A2): spring counts from the reference builders, free-fall heights and orders of
// convergence by simulating, stability limits by running the detector, points from each
// assignment's manifest, the course scenes' coefficients from the framework (A1) or the scene files
// (A2), impulses from the A2 reference, forward kinematics and the time map from the A3 reference.
// Each assignment has its own facts (a1_facts, a2_facts, a3_facts): in
// assignments/ID/handout/*.md a quoted number carries a tag right after it, invisible in the
// rendered page:
//
//     y = 9.775<!-- fact: rk4.com_y_after_0.5s -->
//
// (the number may end a `code span` or **bold** text just before the tag). The test fails when a
// tag names an unknown fact, when the number before a tag disagrees with the code (to the digits
// the text gives), when a fact is never quoted, and when a "Check yourself" section or the points
// table quotes an untagged quantity (the rule is in docs/instructor-guide.md §4a).
//
// Stability facts run the course scene for 10 s per quoted step (a minute in all), and A2's run
// cloth-2022 around its quoted limit: they are checked only in the slow build of this file
// (JELLY_HANDOUT_SLOW, label slow); the fast build checks that they are tagged and known.
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
#include <stdexcept>
#include <string>
#include <vector>

#include "a1_manifest.hpp"
#include "jelly/a1/task_table.hpp"
#include "jelly/a2/collision.hpp"
#include "jelly/a2/friction.hpp"
#include "jelly/a2/task_table.hpp"
#include "jelly/a3/kinematics.hpp"
#include "jelly/a3/time_warp.hpp"
#include "jelly/cloth.hpp"
#include "jelly/cloth_physics.hpp"
#include "jelly/cloth_tasks.hpp"
#include "jelly/cube.hpp"
#include "jelly/cube_scene.hpp"
#include "jelly/cube_tasks.hpp"
#include "jelly/simulator.hpp"
#include "jelly/skeleton/skeleton_files.hpp"
#include "jelly/spheres.hpp"
#include "jelly/world.hpp"
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

// Points are quoted as the grader shows them: to the cent, whatever digits the text gives. A
// rubric change that scales every task (5 becoming 5.33) fails here, where rounding to the digits
// quoted ("5") would let it through.
Fact points_value(std::function<double()> f) {
  return {false, [f](double quoted, int) {
            const double v = f();
            return std::abs(v - quoted) <= 0.005 + 1e-9 ? std::string()
                                                        : "the rubric gives " + show(v);
          }};
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

std::size_t spring_count(void (*CubeTasks::*builder)(const CubeLattice&, std::vector<Spring>&),
                         int n) {
  CubeSpec spec = cube_spec(course_2023_scene());
  spec.n = n;
  const CubeLattice cube(spec, 0);
  std::vector<Spring> springs;
  (cube_tasks(a1::task_table()).*builder)(cube, springs);
  return springs.size();
}

// Shear springs of the course cube whose grid offset has three non-zero components (body
// diagonals).
std::size_t body_diagonals(int n) {
  CubeSpec spec = cube_spec(course_2023_scene());
  spec.n = n;
  const CubeLattice cube(spec, 0);
  std::vector<Spring> springs;
  cube_tasks(a1::task_table()).add_shear_springs(cube, springs);
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
  double hand = 0;  ///< grading.hand_graded_points: the report's points, graded by hand
  std::map<std::string, double> task, category;
};

Rubric rubric() {
  const AssignmentManifest& m = testing::a1_manifest();
  Rubric r;
  r.total = m.autograded_total;
  r.hand = m.hand_graded_points;
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

std::map<std::string, Fact> a1_facts() {
  using K = IntegratorKind;
  std::map<std::string, Fact> f;
  const auto n10 = [](auto builder) {
    return [builder] { return double(spring_count(builder, 10)); };
  };
  f["springs.structural.n10"] = value(n10(&CubeTasks::add_structural_springs));
  f["springs.structural_both_ways.n10"] =
      value([] { return 2.0 * spring_count(&CubeTasks::add_structural_springs, 10); });
  f["springs.shear.n10"] = value(n10(&CubeTasks::add_shear_springs));
  f["springs.shear_face.n10"] = value(
      [] { return double(spring_count(&CubeTasks::add_shear_springs, 10) - body_diagonals(10)); });
  f["springs.shear_body.n10"] = value([] { return double(body_diagonals(10)); });
  f["springs.bending.n10"] = value(n10(&CubeTasks::add_bending_springs));
  f["springs.all.n10"] = value([] {
    return double(spring_count(&CubeTasks::add_structural_springs, 10) +
                  spring_count(&CubeTasks::add_shear_springs, 10) +
                  spring_count(&CubeTasks::add_bending_springs, 10));
  });
  f["course.n"] = value([] { return double(cube_spec(course_2023_scene()).n); });
  f["course.dt"] = value([] { return course_2023_scene().dt; });
  f["course.center_x"] = value([] { return cube_spec(course_2023_scene()).center.x(); });
  f["course.center_y"] = value([] { return cube_spec(course_2023_scene()).center.y(); });
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
  f["points.autograded"] = points_value([] { return rubric().total; });
  // The report's points are the manifest's own (grading.hand_graded_points), not 100 minus the
  // autograded total: raising autograded_total leaves them as they are.
  f["points.report"] = points_value([] { return rubric().hand; });
  for (const char* c : {"springs", "forces", "collision", "integrators"})
    f[std::string("points.") + c] =
        points_value([c = std::string(c)] { return rubric().category.at(c); });
  for (int t = 1; t <= 13; ++t) {
    const std::string id = "A1.T" + std::to_string(t);
    f["points." + id] = points_value([id] { return rubric().task.at(id); });
  }
  f["points.A1.T11+T12"] =
      points_value([] { return rubric().task.at("A1.T11") + rubric().task.at("A1.T12"); });
  return f;
}

// ---- A2, the cloth (issue 20) ----------------------------------------------------------------

// A cloth scene file read as TOML (the course's coefficients are quoted from the scene files, the
// ones a student runs).
const toml::table& cloth_scene(const std::string& name) {
  static std::map<std::string, toml::table> cache;
  auto it = cache.find(name);
  if (it == cache.end())
    it = cache.emplace(name, toml::parse_file((kSource / "scenes" / (name + ".toml")).string()))
             .first;
  return it->second;
}

double scene_number(const std::string& scene, const std::string& path) {
  const auto v = cloth_scene(scene).at_path(path).value<double>();
  if (!v) ADD_FAILURE() << "scenes/" << scene << ".toml has no number " << path;
  return v.value_or(std::nan(""));
}

Vec3 scene_vec3(const toml::node_view<const toml::node> node) {
  const toml::array* a = node.as_array();
  if (!a || a->size() != 3) return Vec3::Constant(std::nan(""));
  return Vec3((*a)[0].value<double>().value_or(std::nan("")),
              (*a)[1].value<double>().value_or(std::nan("")),
              (*a)[2].value<double>().value_or(std::nan("")));
}

// The value every listed key has in every listed scene; NaN (never a quotable number) when they
// differ, so that a handout quoting "the course's kd" fails when the scenes disagree.
double common_number(const std::vector<std::string>& scenes, const std::vector<std::string>& keys) {
  double v = std::nan("");
  bool first = true;
  for (const std::string& scene : scenes)
    for (const std::string& key : keys) {
      const double x = scene_number(scene, key);
      if (first)
        v = x;
      else if (!(x == v))
        return std::nan("");
      first = false;
    }
  return v;
}
const std::vector<std::string> kSpringKeys(const std::string& what) {
  return {"springs.structural." + what, "springs.shear." + what, "springs.bending." + what};
}

// The course cloth (cloth-2022's body) with n particles per edge.
ClothSpec course_cloth(int n) {
  ClothSpec spec;
  spec.n = n;
  spec.size = scene_number("cloth-2022", "body.size");
  spec.mass = scene_number("cloth-2022", "body.mass");
  spec.center = scene_vec3(cloth_scene("cloth-2022").at_path("body.center"));
  return spec;
}

using GridBuilder = void (*ClothTasks::*)(const ClothGrid&, std::vector<Spring>&);

std::vector<Spring> grid_springs(GridBuilder builder, int n) {
  const ClothGrid cloth(course_cloth(n), 0);
  std::vector<Spring> springs;
  (cloth_tasks(a2::task_table()).*builder)(cloth, springs);
  return springs;
}

double grid_count(GridBuilder builder, int n) { return double(grid_springs(builder, n).size()); }

// The rest length every spring of a type has on the course cloth (they are measured from the
// positions, so equal only to rounding: a few 1e-16 m on a cloth 2 m from its centre); NaN when
// two differ by more than 1e-12 relative (a spring of another type among them).
double common_rest_length(GridBuilder builder) {
  const std::vector<Spring> springs = grid_springs(builder, 25);
  if (springs.empty()) return std::nan("");
  const double first = springs.front().rest_length;
  for (const Spring& s : springs)
    if (std::abs(s.rest_length - first) > 1e-12 * first) return std::nan("");
  return first;
}

// Whether a manifest task is a bonus: its `bonus = true` (the grader's key); a manifest without
// the key marks it by category "bonus".
bool is_bonus(const toml::table& task) {
  if (const auto b = task["bonus"].value<bool>()) return *b;
  return task["category"].value<std::string>() == "bonus";
}

// The rubric of an assignment read straight from its manifest: the points of the tasks that are
// not bonus scaled to grading.autograded_total, as the grader does; bonus tasks come on top,
// scaled by the same factor (Rubric::bonus is their sum).
struct ManifestRubric : Rubric {
  double bonus = 0;
};
ManifestRubric rubric_of(const std::string& id) {
  const toml::table m =
      toml::parse_file((kSource / "assignments" / id / "assignment.toml").string());
  ManifestRubric r;
  r.total = m.at_path("grading.autograded_total").value<double>().value_or(std::nan(""));
  r.hand = m.at_path("grading.hand_graded_points").value<double>().value_or(0.0);
  const toml::array* tasks = m["task"].as_array();
  if (!tasks) return r;
  for (const toml::node& t : *tasks)
    if (!is_bonus(*t.as_table()))
      r.raw += t.as_table()->at_path("points").value<double>().value_or(0.0);
  for (const toml::node& t : *tasks) {
    const toml::table& task = *t.as_table();
    const double p = task["points"].value<double>().value_or(0.0) * r.total / r.raw;
    r.task[task["id"].value<std::string>().value_or("")] = p;
    if (is_bonus(task))
      r.bonus += p;
    else
      r.category[task["category"].value<std::string>().value_or("")] += p;
  }
  return r;
}

// The A2 reference's impulses on the handout's examples.
// A free particle falling at 2 m/s onto the top of a kinematic sphere of radius 1 rising at 1 m/s.
double kinematic_example_particle_vy(double e) {
  PointBody p{Vec3(0.0, 1.005, 0.0), Vec3(0.0, -2.0, 0.0), 1.0};
  SphereBody s{Vec3::Zero(), Vec3(0.0, 1.0, 0.0), 1.0, 0.0};
  const Impulse i = a2::collide_particle_sphere(p, s, {e, 0.01});
  if (!i.applied || s.velocity != Vec3(0.0, 1.0, 0.0)) return std::nan("");
  return p.velocity.y();
}

// A course sphere (r = 0.5, 1000 r³ kg) falling at 1 m/s onto a pinned particle, e = 0.
double pinned_example_sphere_vy() {
  const double r = scene_number("cloth-2022", "sphere[0].radius");
  PointBody p{Vec3::Zero(), Vec3::Zero(), 0.0};
  SphereBody s{Vec3(0.0, r + 0.005, 0.0), Vec3(0.0, -1.0, 0.0), r, 1.0 / default_sphere_mass(r)};
  const Impulse i = a2::collide_particle_sphere(p, s, {0.0, 0.01});
  if (!i.applied || p.velocity != Vec3::Zero()) return std::nan("");  // the pin never moves
  return s.velocity.y();
}

// The same pair through the course handout's mass-weighted formula with the pin's mass 0:
// v_a = (m_a u_a + m_b u_b + m_b e (u_b − u_a)) / (m_a + m_b), normal components (N = −y).
double mass_weighted_pinned_vy() {
  const double r = scene_number("cloth-2022", "sphere[0].radius");
  const double m_a = 0.0, m_b = default_sphere_mass(r), e = 0.0;
  const double u_a = 0.0, u_b = -1.0;  // y components
  return (m_a * u_a + m_b * u_b + m_b * e * (u_b - u_a)) / (m_a + m_b);
}

// Two spheres of radius 0.5 on the x axis, touching, a moving at va and b at vb; a kinematic one
// has inverse mass 0. Returns the x velocities after the reference's impulse.
std::pair<double, double> sphere_pair(double ra, double va, bool a_kinematic, double rb, double vb,
                                      bool b_kinematic, double e) {
  SphereBody a{Vec3(-ra, 0.0, 0.0), Vec3(va, 0.0, 0.0), ra,
               a_kinematic ? 0.0 : 1.0 / default_sphere_mass(ra)};
  SphereBody b{Vec3(rb + 0.001, 0.0, 0.0), Vec3(vb, 0.0, 0.0), rb,
               b_kinematic ? 0.0 : 1.0 / default_sphere_mass(rb)};
  if (!a2::collide_spheres(a, b, {e, 0.01}).applied) return {std::nan(""), std::nan("")};
  return {a.velocity.x(), b.velocity.x()};
}

// The friction example: a free particle sliding at 1 m/s along the top of a kinematic sphere,
// hitting it at 1 m/s, e = 0. Returns j, or the sliding speed after friction μ.
double friction_example(double mu, bool want_j) {
  PointBody p{Vec3(0.0, 1.005, 0.0), Vec3(1.0, -1.0, 0.0), 1.0};
  SphereBody s{Vec3::Zero(), Vec3::Zero(), 1.0, 0.0};
  const Impulse i = a2::collide_particle_sphere(p, s, {0.0, 0.01});
  if (!i.applied) return std::nan("");
  if (want_j) return i.j;
  a2::friction_impulse(i, mu, p.inverse_mass, s.inverse_mass, p.velocity, s.velocity);
  if (s.velocity != Vec3::Zero() || p.velocity.y() != 0.0) return std::nan("");
  return p.velocity.x();
}

// Observed order of convergence of A2's reference integrator on the two-particle spring.
double a2_order(IntegratorKind kind) {
  auto error = [kind](double h) {
    Simulator::Options o{kind, h};
    o.detect_instability = false;
    Simulator sim(build_world(testing::two_particle_spring(kind, h), a2::task_table()), o);
    sim.run_until(1.0);
    const double x1 = TwoParticleSpring::exact_x1(1.0);
    const State& st = sim.state();
    return std::max((st.x.col(1) - Vec3(x1, 0, 0)).norm(), (st.x.col(0) - Vec3(-x1, 0, 0)).norm());
  };
  return std::log2(error(2.5e-3) / error(1.25e-3));
}

// cloth-2022 built from its scene file with the World's cloth API and A2's reference.
std::unique_ptr<World> cloth_2022_world() {
  const toml::table& t = cloth_scene("cloth-2022");
  auto world = std::make_unique<World>(a2::task_table());
  ClothSpec spec = course_cloth(static_cast<int>(scene_number("cloth-2022", "body.n")));
  spec.air_drag = scene_number("cloth-2022", "body.air_drag");
  const int cloth = cloth_physics(*world).add_cloth(spec);
  const std::pair<SpringType, const char*> types[] = {{SpringType::Structural, "structural"},
                                                      {SpringType::Shear, "shear"},
                                                      {SpringType::Bending, "bending"}};
  for (const auto& [type, name] : types)
    cloth_physics(*world).build_cloth_springs(
        cloth, type, scene_number("cloth-2022", std::string("springs.") + name + ".ks"),
        scene_number("cloth-2022", std::string("springs.") + name + ".kd"));
  if (const toml::array* spheres = t["sphere"].as_array())
    for (const toml::node& n : *spheres) {
      SphereSpec s;
      s.center = scene_vec3(toml::node_view<const toml::node>(n.as_table()->get("center")));
      s.radius = n.as_table()->at_path("radius").value<double>().value_or(std::nan(""));
      cloth_physics(*world).add_sphere(s);
    }
  ClothCollisionSettings c;
  c.cloth_restitution = scene_number("cloth-2022", "collision.cloth_restitution");
  c.sphere_restitution = scene_number("cloth-2022", "collision.sphere_restitution");
  c.tolerance = scene_number("cloth-2022", "collision.tolerance");
  cloth_physics(*world).set_cloth_collisions(c);
  world->set_gravity(scene_vec3(t.at_path("gravity.acceleration")));
  return world;
}

// cloth-2022 with the course's implicit Euler at step h: stable for the scene's whole duration
// (5 s: the spheres land and settle)?
double cloth_2022_seconds() { return scene_number("cloth-2022", "simulation.duration"); }
bool cloth_2022_implicit_stable(double h) {
  Simulator sim(cloth_2022_world(), {IntegratorKind::ImplicitEuler, h});
  return sim.run_until(cloth_2022_seconds()) == StepResult::Ok;
}

// The quoted limit h is the true one rounded to the digits given: stable half a last digit below,
// unstable half a last digit above.
Fact cloth_2022_implicit_limit(
    std::function<double(double quoted, double half_digit, bool above)> h_at) {
  return {true, [h_at](double quoted, int decimals) {
            const double half = 0.5 * std::pow(10.0, -decimals);
            const double below = h_at(quoted, half, false), above = h_at(quoted, half, true);
            std::string why;
            if (!cloth_2022_implicit_stable(below))
              why += "implicit Euler blows up on cloth-2022 at h = " + show(below) + " ";
            if (cloth_2022_implicit_stable(above))
              why += "implicit Euler runs " + show(cloth_2022_seconds()) +
                     " s of cloth-2022 at h = " + show(above);
            return why;
          }};
}

std::map<std::string, Fact> a2_facts() {
  using K = IntegratorKind;
  std::map<std::string, Fact> f;
  const std::vector<std::string> both = {"cloth-2022", "cloth-2024"};
  f["cloth.n"] = value([both] { return common_number(both, {"body.n"}); });
  f["course.dt"] = value([both] { return common_number(both, {"simulation.dt"}); });
  f["course.kd"] = value([both] { return common_number(both, kSpringKeys("kd")); });
  f["course2022.ks"] = value([] { return common_number({"cloth-2022"}, kSpringKeys("ks")); });
  f["course2024.ks"] = value([] { return common_number({"cloth-2024"}, kSpringKeys("ks")); });
  f["course.air_drag"] = value([both] { return common_number(both, {"body.air_drag"}); });
  f["course.cloth_restitution"] =
      value([both] { return common_number(both, {"collision.cloth_restitution"}); });
  f["course.tolerance"] = value([both] { return common_number(both, {"collision.tolerance"}); });
  f["course.sphere_restitution"] =
      value([] { return common_number({"cloth-2022"}, {"collision.sphere_restitution"}); });
  f["course2022.sphere_mass"] = value([] {
    return default_sphere_mass(common_number(
        {"cloth-2022"},
        {"sphere[0].radius", "sphere[1].radius", "sphere[2].radius", "sphere[3].radius"}));
  });
  f["course2022.sphere_spacing"] = value([] {
    const toml::table& t = cloth_scene("cloth-2022");
    return (scene_vec3(t.at_path("sphere[0].center")) - scene_vec3(t.at_path("sphere[1].center")))
        .norm();
  });
  f["sphere_mass.r1"] = value([] { return default_sphere_mass(1.0); });

  const std::pair<const char*, GridBuilder> builders[] = {
      {"structural", &ClothTasks::add_grid_structural_springs},
      {"shear", &ClothTasks::add_grid_shear_springs},
      {"bending", &ClothTasks::add_grid_bending_springs}};
  for (const auto& [name, builder] : builders) {
    const GridBuilder b = builder;
    for (int n : {5, 25})
      f[std::string("springs.") + name + ".n" + std::to_string(n)] =
          value([b, n] { return grid_count(b, n); });
    f[std::string("rest.") + name] = value([b] { return common_rest_length(b); });
  }
  for (int n : {5, 25})
    f["springs.all.n" + std::to_string(n)] = value([builders, n] {
      double total = 0;
      for (const auto& [name, b] : builders) total += grid_count(b, n);
      return total;
    });
  f["springs.structural_both_ways.n25"] =
      value([] { return 2.0 * grid_count(&ClothTasks::add_grid_structural_springs, 25); });
  // Shear springs along the (1,1) diagonal only: index step n + 1.
  f["springs.shear_one_diagonal.n25"] = value([] {
    double count = 0;
    for (const Spring& s : grid_springs(&ClothTasks::add_grid_shear_springs, 25))
      count += s.b - s.a == 25 + 1;
    return count;
  });

  f["impulse.kinematic_e0.particle_vy"] = value([] { return kinematic_example_particle_vy(0.0); });
  f["impulse.pinned_dynamic.sphere_vy"] = value([] { return pinned_example_sphere_vy(); });
  f["mistake.mass_weighted.pinned_vy"] = value([] { return mass_weighted_pinned_vy(); });
  f["impulse.headon.a_vx"] =
      value([] { return sphere_pair(0.5, 1, false, 0.5, -1, false, 0.8).first; });
  f["impulse.headon.b_vx"] =
      value([] { return sphere_pair(0.5, 1, false, 0.5, -1, false, 0.8).second; });
  f["impulse.kinematic_wall.speed"] = value([] {
    const auto [a, b] = sphere_pair(0.5, 1, false, 0.5, 0, true, 0.8);
    return b == 0.0 ? -a : std::nan("");
  });
  f["impulse.unequal_e0.common_vx"] = value([] {
    const auto [a, b] = sphere_pair(0.5, 1, false, 1.0, 0, false, 0.0);
    return std::abs(a - b) < 1e-15 ? a : std::nan("");
  });
  f["friction.example.j"] = value([] { return friction_example(0.0, true); });
  f["friction.example.mu05_speed"] = value([] { return friction_example(0.5, false); });
  f["friction.example.mu2_speed"] = value([] { return friction_example(2.0, false); });

  for (const auto& [name, kind] : std::map<std::string, K>{{"explicit_euler", K::ExplicitEuler},
                                                           {"implicit_euler", K::ImplicitEuler},
                                                           {"midpoint", K::Midpoint},
                                                           {"rk4", K::RK4}}) {
    const K k = kind;
    f[name + ".order"] = {false, [k](double quoted, int) {
                            const double observed = a2_order(k);
                            return std::abs(observed - quoted) <= 0.3
                                       ? std::string()
                                       : "the observed order is " + show(observed);
                          }};
  }
  f["rk4.real_interval"] = value([] { return -rk4_real_interval(); });
  // Decision 15: the course's implicit Euler on cloth-2022, its limit as a step and as a share
  // above the course's step.
  f["implicit_euler.cloth2022_limit_h"] = cloth_2022_implicit_limit(
      [](double quoted, double half, bool above) { return above ? quoted + half : quoted - half; });
  f["implicit_euler.cloth2022_limit_percent_above_course"] =
      cloth_2022_implicit_limit([](double quoted, double half, bool above) {
        const double dt = scene_number("cloth-2022", "simulation.dt");
        return dt * (1.0 + (above ? quoted + half : quoted - half) / 100.0);
      });

  const Rubric r = rubric_of("a2");
  f["points.autograded"] = points_value([] { return rubric_of("a2").total; });
  f["points.report"] = points_value([] { return rubric_of("a2").hand; });
  for (const char* c : {"springs", "forces", "collision", "integrators"})
    f[std::string("points.") + c] =
        points_value([c = std::string(c)] { return rubric_of("a2").category.at(c); });
  f["points.bonus"] = points_value([] { return rubric_of("a2").bonus; });
  for (const auto& [id, points] : r.task)
    if (id != "A2.COURSE")
      f["points." + id] = points_value([id = id] { return rubric_of("a2").task.at(id); });
  f["points.A2.T9+T10"] = points_value(
      [] { return rubric_of("a2").task.at("A2.T9") + rubric_of("a2").task.at("A2.T10"); });
  return f;
}

// A3's forward kinematics of one course posture (the reference, scale 0.2): bone `bone`'s end, or
// the root's start.
Vec3 a3_course_point(const std::string& amc, int frame, const std::string& bone) {
  const fs::path mocap = kSource / "data" / "mocap";
  const skeleton::SkeletonResult s = skeleton::read_asf(mocap / "skeleton.asf", 0.2);
  if (!s) throw std::runtime_error(s.error->text());
  const skeleton::MotionResult m = skeleton::read_amc(mocap / amc, *s.skeleton);
  if (!m) throw std::runtime_error(m.error->text());
  skeleton::BoneFrames f;
  a3::forward_kinematics(*s.skeleton, m.motion->frames.at(static_cast<std::size_t>(frame)), f);
  const int i = s.skeleton->find(bone).value();
  return bone == "root" ? f.start[static_cast<std::size_t>(i)] : f.end[static_cast<std::size_t>(i)];
}

// A3 (forward kinematics and time warping): the kinematics contract's §8 numbers from the
// reference's forward kinematics, the time map's examples, the points.
std::map<std::string, Fact> a3_facts() {
  std::map<std::string, Fact> f;
  const struct {
    const char *name, *amc;
    int frame;
    const char* bone;
  } points[] = {{"ik.0.root", "IK.amc", 0, "root"},
                {"ik.0.lowerback", "IK.amc", 0, "lowerback"},
                {"ik.0.head", "IK.amc", 0, "head"},
                {"ik.0.rfingers", "IK.amc", 0, "rfingers"},
                {"walk.0.root", "walk.amc", 0, "root"},
                {"walk.0.head", "walk.amc", 0, "head"},
                {"walk.0.rfingers", "walk.amc", 0, "rfingers"},
                {"walk.147.root", "walk.amc", 147, "root"},
                {"walk.147.rfingers", "walk.amc", 147, "rfingers"}};
  for (const auto& p : points)
    for (int k = 0; k < 3; ++k)
      f[std::string("fk.") + p.name + "." + "xyz"[k]] =
          value([p, k] { return a3_course_point(p.amc, p.frame, p.bone)[k]; });
  f["time.retime.s1"] = value([] { return a3::time_map(1, {148, 200, -1, -1}); });
  f["time.retime.s100"] = value([] { return a3::time_map(100, {148, 200, -1, -1}); });
  f["time.punch.s151"] = value([] { return a3::time_map(151, {450, 450, 160, 150}); });
  f["points.autograded"] = points_value([] { return rubric_of("a3").total; });
  f["points.report"] = points_value([] { return rubric_of("a3").hand; });
  f["points.bonus"] = points_value([] { return rubric_of("a3").bonus; });
  f["points.fk"] = points_value([] { return rubric_of("a3").category.at("forward kinematics"); });
  f["points.warp"] = points_value([] { return rubric_of("a3").category.at("time warping"); });
  for (const char* id : {"A3.T1", "A3.T2", "A3.T3", "A3.T4"})
    f[std::string("points.") + id] =
        points_value([id = std::string(id)] { return rubric_of("a3").task.at(id); });
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

// The assignments whose handouts this test checks, with their facts.
const std::vector<std::string> kAssignments = {"a1", "a2", "a3"};

std::map<std::string, Fact> facts(const std::string& id) {
  if (id == "a3") return a3_facts();
  return id == "a1" ? a1_facts() : a2_facts();
}

std::vector<fs::path> handout_pages(const std::string& id) {
  std::vector<fs::path> pages;
  for (const auto& e : fs::directory_iterator(kSource / "assignments" / id / "handout"))
    if (e.path().extension() == ".md") pages.push_back(e.path());
  std::sort(pages.begin(), pages.end());
  return pages;
}

const std::regex kTag(R"(<!-- fact: ([A-Za-z0-9_.+]+) -->)");
// The number right before a tag (a Unicode or ASCII minus, digits, decimals), maybe closing a
// code span or bold text.
const std::regex kNumberBeforeTag("((?:\xE2\x88\x92|-)?[0-9]+(?:\\.[0-9]+)?)(?:`|\\*\\*)?$");

std::vector<Tag> tags(const std::string& id) {
  std::vector<Tag> out;
  for (const fs::path& page : handout_pages(id)) {
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
  for (const std::string& id : kAssignments) {
    SCOPED_TRACE("assignments/" + id + "/handout/");
    const std::map<std::string, Fact> known = facts(id);
    std::set<std::string> used;
    const std::vector<Tag> all = tags(id);
    ASSERT_FALSE(all.empty()) << "no <!-- fact: ... --> tags in assignments/" << id << "/handout/";
    for (const Tag& t : all) {
      const std::string where =
          id + "/handout/" + t.file + ":" + std::to_string(t.line) + ": fact " + t.fact;
      const auto f = known.find(t.fact);
      if (f == known.end()) {
        ADD_FAILURE() << where
                      << ": no such fact (tests/handout/test_handout_facts.cpp lists them)";
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
      EXPECT_TRUE(used.count(name)) << "fact " << name << " is quoted nowhere in assignments/" << id
                                    << "/handout/: remove it or quote it";
  }
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
  for (const std::string& id : kAssignments)
    for (const fs::path& page : handout_pages(id)) {
      const std::vector<std::string> lines = lines_of(page);
      bool in_check = false;
      for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string& l = lines[i];
        if (l.rfind("## ", 0) == 0)
          in_check = l == "## Check yourself" || l == "## 3. Check yourself";
        const bool points_row = std::regex_search(l, std::regex(R"(^\| \[A[0-9]+\.T)")) ||
                                l.rfind("| [Report]", 0) == 0;
        if (!in_check && !points_row) continue;
        for (const std::string& n : untagged_quantities(l))
          ADD_FAILURE() << id << "/handout/" << page.filename().string() << ":" << i + 1
                        << ": the number " << n
                        << " has no <!-- fact: ... --> tag (docs/instructor-guide.md §4a): " << l;
      }
    }
}

// Points are checked to the cent: the old rule (the digits the text gives) let a rubric change that
// turned every quoted "5" into 5.33 through.
TEST(HandoutFacts, APointsFactFailsWhenARubricChangeScalesTheTask) {
  const double scaled = 5.0 * 80.0 / 85.0;  // one other task's points raised by 5
  EXPECT_EQ(value([=] { return scaled; }).check(5.0, 0), "") << "the rounding rule's blind spot";
  EXPECT_NE(points_value([=] { return scaled; }).check(5.0, 0), "");
  EXPECT_EQ(points_value([] { return 5.0; }).check(5.0, 0), "");
  EXPECT_EQ(points_value([] { return 7.5; }).check(7.5, 1), "");
  EXPECT_EQ(points_value([] { return 10.0 / 3.0; }).check(3.33, 2), "") << "quoted to the cent";
  EXPECT_NE(points_value([] { return 10.0 / 3.0; }).check(3.3, 1), "");
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
