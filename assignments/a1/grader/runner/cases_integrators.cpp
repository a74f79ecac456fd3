// A1.T10–T13 cases: each course integrator stepped on framework-provided systems only (free fall,
// the linear two-particle spring, the linearised damped cube): no student force, spring or terrain
// code runs, so a wrong spring sign cannot fail an integrator test. Free fall and convergence are
// the mass_spring module's slot-level cases (grader/runner/mass_spring_cases.cpp); the cube's are
// A1's own.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "cases.hpp"
#include "jelly/test_systems.hpp"
#include "jelly/world.hpp"
#include "mass_spring_cases.hpp"

namespace jelly::grade {

namespace {

// The free fall's start (the mass_spring module's integrator_free_fall): three particles, the
// first dropped from rest at y = 11 m.
FreeFallStart a1_free_fall() {
  FreeFallStart start{Vec3Array(3, 3), Vec3Array(3, 3),
                      "a particle dropped from rest at y = 11 m (contract §9)"};
  start.x << -4.8, 0.0, 1.0, 11.0, 5.0, 2.0, 0.0, 2.0, 3.0;
  start.v << 0.0, 1.0, 0.0, 0.0, 0.0, 3.0, 0.0, 0.5, 0.0;
  return start;
}

// The prepared cube (params.cube) linearised about its rest shape, stiffness params.ks, dampers
// params.kd, gravity params.gravity (none when absent); no student code.
std::unique_ptr<LinearSystem> linear_cube(const Params& params, const Json& input) {
  World world{TaskTable{}};
  add_prepared_cube(world, params, input, params.number("ks"), params.number("kd"));
  if (params.has("gravity")) world.set_gravity(params.vec("gravity"));
  const Vec3Array rest = world.state().x;
  return std::make_unique<LinearSystem>(world, rest);
}

// The cube at rest, positions moved by params.dx·U and velocities params.dv·U (U uniform in
// [−1, 1) from params.seed).
State perturbed_cube_state(const Params& params, const Json& input) {
  World world{TaskTable{}};
  add_prepared_cube(world, params, input, params.number("ks"), params.number("kd"));
  State s = world.state();
  Sequence r(static_cast<std::uint64_t>(params.integer("seed")));
  const double dx = params.number("dx"), dv = params.number("dv");
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    s.x.col(i) += dx * r.next3();
    s.v.col(i) = dv * r.next3();
  }
  return s;
}

// One step of params.h from the perturbed state of the linear cube.
void run_single_step(const TaskTable& t, const Params& params, const Json& input, Outputs& out) {
  const IntegratorMethod& m = integrator_method(params);
  const double h = params.number("h");
  auto system = linear_cube(params, input);
  State s = perturbed_cube_state(params, input);
  step_n(t.*(m.member), *system, s, h, 1);
  char what[96];
  std::snprintf(what, sizeof what, "after ONE step of h = %g s of the damped linear cube", h);
  out.array("x", s.x, std::string("positions ") + what + " [m]");
  out.array("v", s.v, std::string("velocities ") + what + " [m/s]");
}

// Energy of the linear cube over params.steps steps of params.h from its perturbed state: with
// damping on it must not grow.
void run_energy(const TaskTable& t, const Params& params, const Json& input, Outputs& out) {
  const IntegratorMethod& m = integrator_method(params);
  const double h = params.number("h");
  const long steps = params.integer("steps");
  auto system = linear_cube(params, input);
  State s = perturbed_cube_state(params, input);
  const double e0 = system->energy(s);
  double max_ratio = 1.0;
  Workspace w;
  for (long i = 0; i < steps; ++i) {
    w.resize(s.size());
    (t.*(m.member))(*system, s, h, w);
    const double e = system->energy(s);
    max_ratio = std::isfinite(e) ? std::max(max_ratio, e / e0) : e;
    if (!std::isfinite(e)) break;
  }
  char what[120];
  std::snprintf(what, sizeof what, "over %ld steps of %g s of the damped linear cube", steps, h);
  out.value("max_energy_ratio", max_ratio,
            std::string("largest E(t)/E(0) ") + what + " (damping on: must stay ≤ 1)");
  out.value("final_energy_ratio", system->energy(s) / e0, std::string("E(end)/E(0) ") + what);
}

}  // namespace

// Every generator takes params.method (explicit_euler, implicit_euler, midpoint, rk4).
void register_integrator_cases(Registry& r) {
  register_integrator_free_fall(r, a1_free_fall());
  r.add({"integrator_single_step", "one step of one integrator on the damped linear cube",
         &prepare_cube_springs,
         [](const TaskTable& t, const Params& p, const Json& in, Outputs& o) {
           run_single_step(t, p, in, o);
         }});
  register_integrator_convergence(r);
  r.add({"integrator_energy", "one integrator's energy on the damped linear cube",
         &prepare_cube_springs,
         [](const TaskTable& t, const Params& p, const Json& in, Outputs& o) {
           run_energy(t, p, in, o);
         }});
}

}  // namespace jelly::grade
