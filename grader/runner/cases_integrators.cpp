// A1.T10–T13 cases: each course integrator stepped on framework-provided systems only (free fall,
// the linear two-particle spring, the linearised damped cube): no student force, spring or terrain
// code runs, so a wrong spring sign cannot fail an integrator test.
#include <cmath>
#include <cstdio>

#include "harness.hpp"
#include "jelly/test_systems.hpp"
#include "jelly/world.hpp"

namespace jelly::grade {

namespace {

struct Method {
  const char* prefix;  // case id prefix
  const char* name;    // the student's function
  StepFunction TaskTable::*member;
};

const Method kMethods[] = {
    {"a1.t10.explicit_euler", "explicit_euler_step", &TaskTable::explicit_euler_step},
    {"a1.t11.implicit_euler", "implicit_euler_step", &TaskTable::implicit_euler_step},
    {"a1.t12.midpoint", "midpoint_step", &TaskTable::midpoint_step},
    {"a1.t13.rk4", "rk4_step", &TaskTable::rk4_step},
};

void step_n(StepFunction fn, System& system, State& s, double h, long n) {
  Workspace w;
  w.resize(system.particle_count());
  for (long i = 0; i < n; ++i) {
    w.resize(system.particle_count());
    fn(system, s, h, w);
  }
}

// Free fall of three particles for 0.5 s at h = 1 ms (contract §9).
void run_free_fall(const Method& m, const TaskTable& t, Outputs& out) {
  FreeFallSystem system(3, Vec3(0.0, -9.8, 0.0));
  State s;
  s.resize(3);
  s.x << -4.8, 0.0, 1.0, 11.0, 5.0, 2.0, 0.0, 2.0, 3.0;
  s.v << 0.0, 1.0, 0.0, 0.0, 0.0, 3.0, 0.0, 0.5, 0.0;
  step_n(t.*(m.member), system, s, 1e-3, 500);
  out.value("y0", s.x(1, 0),
            "height after 500 steps of 1 ms of a particle dropped from rest at y = 11 m (contract §9) [m]");
  out.array("x", s.x, "positions of three falling particles after 0.5 s [m]");
  out.array("v", s.v, "velocities of three falling particles after 0.5 s [m/s]");
}

// The small cube linearised about its rest shape, with gravity and dampers (no student code).
std::unique_ptr<LinearSystem> linear_cube(const Json& input, bool gravity, double kd) {
  World world{TaskTable{}};
  add_small_cube(world, input, 2000.0, kd);
  if (gravity) world.set_gravity(Vec3(0.0, -9.8, 0.0));
  const Vec3Array rest = world.state().x;
  return std::make_unique<LinearSystem>(world, rest);
}

State perturbed_cube_state(const Json& input, std::uint64_t seed, double dx, double dv) {
  World world{TaskTable{}};
  add_small_cube(world, input, 2000.0, 60.0);
  State s = world.state();
  Sequence r(seed);
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    s.x.col(i) += dx * Vec3(r.next(), r.next(), r.next());
    s.v.col(i) = dv * Vec3(r.next(), r.next(), r.next());
  }
  return s;
}

// One step from a given state of the damped linear cube.
void run_single_step(const Method& m, const TaskTable& t, const Json& input, double h,
                     std::uint64_t seed, Outputs& out) {
  auto system = linear_cube(input, true, 60.0);
  State s = perturbed_cube_state(input, seed, 0.05, 1.0);
  step_n(t.*(m.member), *system, s, h, 1);
  char what[96];
  std::snprintf(what, sizeof what, "after ONE step of h = %g s of the damped linear 3×3×3 cube", h);
  out.array("x", s.x, std::string("positions ") + what + " [m]");
  out.array("v", s.v, std::string("velocities ") + what + " [m/s]");
}

// Observed order on the linear two-particle spring (contract §9).
void run_convergence(const Method& m, const TaskTable& t, Outputs& out) {
  const double hs[] = {1e-2, 5e-3, 2.5e-3, 1.25e-3};
  std::vector<double> errors;
  for (double h : hs) {
    auto system = make_linear_two_particle_spring(0.1);
    State s = TwoParticleSpring::initial_state(0.1);
    step_n(t.*(m.member), *system, s, h, std::lround(1.0 / h));
    const double exact = TwoParticleSpring::exact_x1(1.0, 0.1);
    const double e = std::max(std::abs(s.x(0, 1) - exact), std::abs(s.x(0, 0) + exact));
    errors.push_back(e);
  }
  out.values("errors", errors,
             "largest position error at t = 1 s on the two-particle spring for h = 1e-2, 5e-3, 2.5e-3, 1.25e-3 [m]");
  out.value("order", std::log2(errors[2] / errors[3]),
            "observed order of accuracy from the last two step sizes (log2 of the error ratio)");
}

// Energy of the damped linear cube over 1 s (no gravity): with damping it must not grow.
void run_energy(const Method& m, const TaskTable& t, const Json& input, Outputs& out) {
  auto system = linear_cube(input, false, 60.0);
  State s = perturbed_cube_state(input, 5, 0.05, 1.0);
  const double e0 = system->energy(s);
  double max_ratio = 1.0;
  Workspace w;
  for (int i = 0; i < 2000; ++i) {
    w.resize(s.size());
    (t.*(m.member))(*system, s, 5e-4, w);
    const double e = system->energy(s);
    max_ratio = std::isfinite(e) ? std::max(max_ratio, e / e0) : e;
    if (!std::isfinite(e)) break;
  }
  out.value("max_energy_ratio", max_ratio,
            "largest E(t)/E(0) over 1 s of the damped linear cube at h = 0.5 ms (damping on: must stay ≤ 1)");
  out.value("final_energy_ratio", system->energy(s) / e0, "E(1 s)/E(0) of the damped linear cube");
}

}  // namespace

void register_integrator_cases(Registry& r) {
  for (const Method& m : kMethods) {
    const std::string p = m.prefix;
    r.add({p + ".free_fall", std::string(m.name) + " in free fall for 0.5 s", nullptr,
           [m](const TaskTable& t, const Json&, Outputs& o) { run_free_fall(m, t, o); }});
    r.add({p + ".single_step", std::string(m.name) + ": one step of 1 ms of the damped linear cube",
           &prepare_small_cube_springs,
           [m](const TaskTable& t, const Json& in, Outputs& o) { run_single_step(m, t, in, 1e-3, 3, o); }});
    r.add({p + ".single_step_large", std::string(m.name) + ": one step of 5 ms of the damped linear cube",
           &prepare_small_cube_springs,
           [m](const TaskTable& t, const Json& in, Outputs& o) { run_single_step(m, t, in, 5e-3, 17, o); }});
    r.add({p + ".convergence", std::string(m.name) + ": order of accuracy on the two-particle spring", nullptr,
           [m](const TaskTable& t, const Json&, Outputs& o) { run_convergence(m, t, o); }});
    r.add({p + ".energy", std::string(m.name) + ": energy of the damped linear cube never grows",
           &prepare_small_cube_springs,
           [m](const TaskTable& t, const Json& in, Outputs& o) { run_energy(m, t, in, o); }});
  }
}

}  // namespace jelly::grade
