// A1.T10–T13 cases: each course integrator stepped on framework-provided systems only (free fall,
// the linear two-particle spring, the linearised damped cube): no student force, spring or terrain
// code runs, so a wrong spring sign cannot fail an integrator test.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "cases.hpp"
#include "jelly/test_systems.hpp"
#include "jelly/world.hpp"

namespace jelly::grade {

namespace {

struct Method {
  const char* key;   // params.method
  const char* name;  // the student's function
  StepFunction TaskTable::*member;
};

const Method kMethods[] = {
    {"explicit_euler", "explicit_euler_step", &TaskTable::explicit_euler_step},
    {"implicit_euler", "implicit_euler_step", &TaskTable::implicit_euler_step},
    {"midpoint", "midpoint_step", &TaskTable::midpoint_step},
    {"rk4", "rk4_step", &TaskTable::rk4_step},
};

const Method& method(const Params& params) {
  const std::string key = params.text("method");
  for (const Method& m : kMethods)
    if (key == m.key) return m;
  throw std::runtime_error(
      "params.method: expected explicit_euler, implicit_euler, midpoint or rk4, got " + key);
}

void step_n(StepFunction fn, System& system, State& s, double h, long n) {
  Workspace w;
  w.resize(system.particle_count());
  for (long i = 0; i < n; ++i) {
    w.resize(system.particle_count());
    fn(system, s, h, w);
  }
}

// Free fall of three particles (contract §9): params.steps steps of params.h.
void run_free_fall(const TaskTable& t, const Params& params, Outputs& out) {
  const Method& m = method(params);
  const double h = params.number("h");
  const long steps = params.integer("steps");
  FreeFallSystem system(3, Vec3(0.0, -9.8, 0.0));
  State s;
  s.resize(3);
  s.x << -4.8, 0.0, 1.0, 11.0, 5.0, 2.0, 0.0, 2.0, 3.0;
  s.v << 0.0, 1.0, 0.0, 0.0, 0.0, 3.0, 0.0, 0.5, 0.0;
  step_n(t.*(m.member), system, s, h, steps);
  char what[160];
  std::snprintf(
      what, sizeof what,
      "after %ld steps of %g s of a particle dropped from rest at y = 11 m (contract §9) [m]",
      steps, h);
  out.value("y0", s.x(1, 0), std::string("height ") + what);
  out.array("x", s.x, "positions of three falling particles at the end [m]");
  out.array("v", s.v, "velocities of three falling particles at the end [m/s]");
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
  const Method& m = method(params);
  const double h = params.number("h");
  auto system = linear_cube(params, input);
  State s = perturbed_cube_state(params, input);
  step_n(t.*(m.member), *system, s, h, 1);
  char what[96];
  std::snprintf(what, sizeof what, "after ONE step of h = %g s of the damped linear cube", h);
  out.array("x", s.x, std::string("positions ") + what + " [m]");
  out.array("v", s.v, std::string("velocities ") + what + " [m/s]");
}

// Observed order on the linear two-particle spring (contract §9), damping params.damping, one
// run to t = 1 s per step size in params.h (at least two).
void run_convergence(const TaskTable& t, const Params& params, Outputs& out) {
  const Method& m = method(params);
  const double damping = params.number("damping");
  std::vector<double> hs;
  for (const Json& h : params.json().at("h")) hs.push_back(h.get<double>());
  if (hs.size() < 2) throw std::runtime_error("params.h: expected at least two step sizes");
  std::vector<double> errors;
  std::string list;
  for (double h : hs) {
    auto system = make_linear_two_particle_spring(damping);
    State s = TwoParticleSpring::initial_state(damping);
    step_n(t.*(m.member), *system, s, h, std::lround(1.0 / h));
    const double exact = TwoParticleSpring::exact_x1(1.0, damping);
    const double e = std::max(std::abs(s.x(0, 1) - exact), std::abs(s.x(0, 0) + exact));
    errors.push_back(e);
    char b[32];
    std::snprintf(b, sizeof b, "%s%g", list.empty() ? "" : ", ", h);
    list += b;
  }
  const std::size_t k = errors.size();
  out.values(
      "errors", errors,
      "largest position error at t = 1 s on the two-particle spring for h = " + list + " [m]");
  out.value("order", std::log2(errors[k - 2] / errors[k - 1]),
            "observed order of accuracy from the last two step sizes (log2 of the error ratio)");
}

// Energy of the linear cube over params.steps steps of params.h from its perturbed state: with
// damping on it must not grow.
void run_energy(const TaskTable& t, const Params& params, const Json& input, Outputs& out) {
  const Method& m = method(params);
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
  r.add({"integrator_free_fall", "one integrator on three particles in free fall", nullptr,
         [](const TaskTable& t, const Params& p, const Json&, Outputs& o) {
           run_free_fall(t, p, o);
         }});
  r.add({"integrator_single_step", "one step of one integrator on the damped linear cube",
         &prepare_cube_springs,
         [](const TaskTable& t, const Params& p, const Json& in, Outputs& o) {
           run_single_step(t, p, in, o);
         }});
  r.add({"integrator_convergence", "one integrator's order of accuracy on the two-particle spring",
         nullptr, [](const TaskTable& t, const Params& p, const Json&, Outputs& o) {
           run_convergence(t, p, o);
         }});
  r.add({"integrator_energy", "one integrator's energy on the damped linear cube",
         &prepare_cube_springs,
         [](const TaskTable& t, const Params& p, const Json& in, Outputs& o) {
           run_energy(t, p, in, o);
         }});
}

}  // namespace jelly::grade
