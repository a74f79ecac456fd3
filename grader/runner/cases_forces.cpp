// A1.T4–T5 cases: spring_force and damper_force on hand-made springs, and a small cube whose
// springs come from the REFERENCE (stored in the case input), moved by the framework's symplectic
// Euler. The spring scene has kd = 0 and the damper scene ks = 0, so each scene exercises one task.
#include <cmath>
#include <cstdio>

#include "harness.hpp"
#include "jelly/integrator.hpp"
#include "jelly/world.hpp"

namespace jelly::grade {

namespace {

struct SpringInput {
  const char* label;
  Vec3 xa, xb, va, vb;
  double k;       // ks or kd
  double rest;    // rest length (spring_force only)
  double degenerate;
};

std::vector<SpringInput> spring_inputs() {
  const Vec3 o = Vec3::Zero();
  return {
      {"stretched along x (|d| = 1.5, rest 1, ks 10)", {1.5, 0, 0}, o, o, o, 10.0, 1.0, 1e-12},
      {"compressed along y (|d| = 0.5, rest 1, ks 10)", {0, 2.5, 0}, {0, 2.0, 0}, o, o, 10.0, 1.0, 1e-12},
      {"particle b on the other side (d points along −x)", {0, 0, 0}, {1.5, 0, 0}, o, o, 10.0, 1.0, 1e-12},
      {"at its rest length (a diagonal)", {1, 1, 1}, {0, 0, 0}, o, o, 2000.0, std::sqrt(3.0), 1e-12},
      {"a general 3-D spring (ks 2000, rest 1.3)", {0.3, -1.2, 2.5}, {-0.7, 0.4, 1.1}, o, o, 2000.0, 1.3, 1e-12},
      {"very stiff, tiny stretch (ks 1e6)", {0.0, 0.0, 1.0 + 1e-6}, {0, 0, 0}, o, o, 1e6, 1.0, 1e-12},
  };
}

std::vector<SpringInput> degenerate_springs() {
  const Vec3 o = Vec3::Zero();
  return {
      {"shorter than the degenerate length (|d| = 1e-14): must be zero", {1e-14, 0, 0}, o, o, o, 10.0, 1.0, 1e-12},
      {"both particles at the same place: must be zero, never NaN", {0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, o, o, 10.0, 1.0, 1e-12},
      {"just longer than the degenerate length (|d| = 2e-12)", {0, 2e-12, 0}, o, o, o, 10.0, 1.0, 1e-12},
  };
}

std::vector<SpringInput> damper_inputs() {
  const Vec3 o = Vec3::Zero();
  return {
      {"separating along the spring (v_a = (2,0,0), kd 5)", {1, 0, 0}, o, {2, 0, 0}, o, 5.0, 0, 1e-12},
      {"approaching along the spring", {1, 0, 0}, o, {-2, 0, 0}, o, 5.0, 0, 1e-12},
      {"velocity across the spring: must be zero", {1, 0, 0}, o, {0, 3, -1}, o, 5.0, 0, 1e-12},
      {"both moving together: must be zero", {0.2, 0.4, 0.1}, {1, 1, 1}, {1, 2, 3}, {1, 2, 3}, 5.0, 0, 1e-12},
      {"b moving, a still", {0, 0, 0}, {0, 1.5, 0}, o, {0.3, -0.8, 0.1}, 60.0, 0, 1e-12},
      {"a general 3-D damper (kd 60)", {0.3, -1.2, 2.5}, {-0.7, 0.4, 1.1}, {0.5, 0.1, -0.3}, {-0.2, 0.6, 0.9}, 60.0, 0, 1e-12},
  };
}

std::vector<SpringInput> degenerate_dampers() {
  const Vec3 o = Vec3::Zero();
  return {
      {"shorter than the degenerate length: must be zero", {1e-14, 0, 0}, o, {1, 1, 1}, o, 5.0, 0, 1e-12},
      {"both particles at the same place: must be zero, never NaN", {2, 2, 2}, {2, 2, 2}, {1, 0, 0}, o, 5.0, 0, 1e-12},
      {"just longer than the degenerate length (|d| = 2e-12), separating", {0, 2e-12, 0}, o, {0, 1, 0}, o, 5.0, 0, 1e-12},
  };
}

std::vector<SpringInput> random_inputs(std::uint64_t seed, int count) {
  Sequence r(seed);
  std::vector<SpringInput> out;
  for (int i = 0; i < count; ++i) {
    SpringInput s{"", Vec3(3 * r.next(), 3 * r.next(), 3 * r.next()),
                  Vec3(3 * r.next(), 3 * r.next(), 3 * r.next()),
                  Vec3(2 * r.next(), 2 * r.next(), 2 * r.next()),
                  Vec3(2 * r.next(), 2 * r.next(), 2 * r.next()),
                  1000.0 * (1.5 + r.next()), 1.0 + 0.9 * r.next(), 1e-12};
    out.push_back(s);
  }
  return out;
}

std::string describe(const SpringInput& s, int i, bool damper) {
  if (s.label[0] != '\0') return s.label;
  char buf[256];
  if (damper)
    std::snprintf(buf, sizeof buf, "random damper #%d: x_a=(%.3g,%.3g,%.3g) x_b=(%.3g,%.3g,%.3g) v_a=(%.3g,%.3g,%.3g) v_b=(%.3g,%.3g,%.3g) kd=%.4g",
                  i, s.xa.x(), s.xa.y(), s.xa.z(), s.xb.x(), s.xb.y(), s.xb.z(), s.va.x(), s.va.y(),
                  s.va.z(), s.vb.x(), s.vb.y(), s.vb.z(), s.k);
  else
    std::snprintf(buf, sizeof buf, "random spring #%d: x_a=(%.3g,%.3g,%.3g) x_b=(%.3g,%.3g,%.3g) ks=%.4g rest=%.4g",
                  i, s.xa.x(), s.xa.y(), s.xa.z(), s.xb.x(), s.xb.y(), s.xb.z(), s.k, s.rest);
  return buf;
}

void run_springs(const TaskTable& t, const std::vector<SpringInput>& in, Outputs& out) {
  for (std::size_t i = 0; i < in.size(); ++i) {
    const SpringInput& s = in[i];
    char name[32];
    std::snprintf(name, sizeof name, "f%02zu", i);
    out.vec(name, t.spring_force(s.xa, s.xb, s.k, s.rest, s.degenerate),
            "spring_force on a: " + describe(s, static_cast<int>(i), false));
  }
}

void run_dampers(const TaskTable& t, const std::vector<SpringInput>& in, Outputs& out) {
  for (std::size_t i = 0; i < in.size(); ++i) {
    const SpringInput& s = in[i];
    char name[32];
    std::snprintf(name, sizeof name, "f%02zu", i);
    out.vec(name, t.damper_force(s.xa, s.xb, s.va, s.vb, s.k, s.degenerate),
            "damper_force on a: " + describe(s, static_cast<int>(i), true));
  }
}

// The small cube, deformed and moving, stepped with the framework's symplectic Euler; positions
// after 100, 200 and 300 steps of 1 ms.
void run_cube_scene(const TaskTable& tasks, const Json& input, double ks, double kd, Outputs& out) {
  World world(tasks);
  add_small_cube(world, input, ks, kd);
  State& s = world.state();
  Sequence r(7);
  const Vec3 c = s.x.rowwise().mean();
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    s.x.col(i) = c + 1.15 * (s.x.col(i) - c) + 0.05 * Vec3(r.next(), r.next(), r.next());
    s.v.col(i) = 0.5 * Vec3(r.next(), r.next(), r.next());
  }
  Workspace w;
  w.resize(s.size());
  for (int step = 1; step <= 300; ++step) {
    symplectic_euler_step(world, s, 1e-3, w);
    if (step % 100 == 0)
      out.array("x_step" + std::to_string(step), s.x,
                "positions of the 27 particles after " + std::to_string(step) +
                    " steps of 1 ms (framework symplectic Euler, your forces) [m]");
  }
}

}  // namespace

void register_force_cases(Registry& r) {
  r.add({"a1.t4.spring_force.values", "spring_force on hand-made springs", nullptr,
         [](const TaskTable& t, const Json&, Outputs& o) { run_springs(t, spring_inputs(), o); }});
  r.add({"a1.t4.spring_force.degenerate", "spring_force on (nearly) zero-length springs", nullptr,
         [](const TaskTable& t, const Json&, Outputs& o) { run_springs(t, degenerate_springs(), o); }});
  r.add({"a1.t4.spring_force.random", "spring_force on 12 random springs", nullptr,
         [](const TaskTable& t, const Json&, Outputs& o) { run_springs(t, random_inputs(41, 12), o); }});
  r.add({"a1.t4.scene.cube", "a deformed 3×3×3 cube with springs only (kd = 0)",
         &prepare_small_cube_springs,
         [](const TaskTable& t, const Json& in, Outputs& o) { run_cube_scene(t, in, 2000.0, 0.0, o); }});
  r.add({"a1.t5.damper_force.values", "damper_force on hand-made dampers", nullptr,
         [](const TaskTable& t, const Json&, Outputs& o) { run_dampers(t, damper_inputs(), o); }});
  r.add({"a1.t5.damper_force.degenerate", "damper_force on (nearly) zero-length dampers", nullptr,
         [](const TaskTable& t, const Json&, Outputs& o) { run_dampers(t, degenerate_dampers(), o); }});
  r.add({"a1.t5.damper_force.random", "damper_force on 12 random dampers", nullptr,
         [](const TaskTable& t, const Json&, Outputs& o) { run_dampers(t, random_inputs(43, 12), o); }});
  r.add({"a1.t5.scene.cube", "a moving 3×3×3 cube with dampers only (ks = 0)",
         &prepare_small_cube_springs,
         [](const TaskTable& t, const Json& in, Outputs& o) { run_cube_scene(t, in, 0.0, 5.0, o); }});
}

}  // namespace jelly::grade
