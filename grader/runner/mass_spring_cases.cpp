// Slot-level cases of the mass_spring task module: spring_force, damper_force and the course
// integrators (mass_spring_cases.hpp). Each assignment that has these tasks registers them and
// runs them with its own case files.
#include "mass_spring_cases.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "jelly/spring.hpp"
#include "jelly/test_systems.hpp"

namespace jelly::grade {

// ----- spring_force, damper_force -----

namespace {

struct SpringInput {
  std::string label;
  Vec3 xa, xb, va, vb;
  double k;     // ks or kd
  double rest;  // rest length (spring_force only)
  double degenerate;
};

// The degenerate length of the inputs that do not give one: a body of 1 m grid spacing.
constexpr double kDefaultDegenerate = degenerate_length_for(1.0);

// Hand-made inputs: params.springs (spring_force: label, xa, xb, ks, rest) or params.dampers
// (damper_force: label, xa, xb, va, vb, kd); degenerate length that of a 1 m spacing unless given.
std::vector<SpringInput> listed_inputs(const Params& params, bool damper) {
  std::vector<SpringInput> out;
  for (const Params& p : params.list(damper ? "dampers" : "springs")) {
    SpringInput s;
    s.label = p.text("label");
    s.xa = p.vec("xa");
    s.xb = p.vec("xb");
    s.va = damper ? p.vec("va") : Vec3::Zero();
    s.vb = damper ? p.vec("vb") : Vec3::Zero();
    s.k = p.number(damper ? "kd" : "ks");
    s.rest = damper ? 0.0 : p.number("rest");
    s.degenerate = p.number("degenerate", kDefaultDegenerate);
    out.push_back(s);
  }
  return out;
}

// Random inputs: params.random = { seed, count, position, velocity, k_scale, k_offset,
// rest_offset, rest_scale }: positions position·U, velocities velocity·U, stiffness
// k_scale·(k_offset + U), rest length rest_offset + rest_scale·U, U uniform in [−1, 1).
std::vector<SpringInput> random_inputs(const Params& random) {
  Sequence r(static_cast<std::uint64_t>(random.integer("seed")));
  const long count = random.integer("count");
  const double px = random.number("position"), pv = random.number("velocity");
  const double ks = random.number("k_scale"), k0 = random.number("k_offset");
  const double r0 = random.number("rest_offset"), rs = random.number("rest_scale");
  std::vector<SpringInput> out;
  for (long i = 0; i < count; ++i) {
    SpringInput s;
    s.xa = px * r.next3();  // draw order is part of the case (Sequence::next3)
    s.xb = px * r.next3();
    s.va = pv * r.next3();
    s.vb = pv * r.next3();
    s.k = ks * (k0 + r.next());
    s.rest = r0 + rs * r.next();
    s.degenerate = kDefaultDegenerate;
    out.push_back(s);
  }
  return out;
}

std::vector<SpringInput> inputs(const Params& params, bool damper) {
  return params.has("random") ? random_inputs(params.table("random"))
                              : listed_inputs(params, damper);
}

std::string describe(const SpringInput& s, int i, bool damper) {
  if (!s.label.empty()) return s.label;
  char buf[256];
  if (damper)
    std::snprintf(buf, sizeof buf,
                  "random damper #%d: x_a=(%.3g,%.3g,%.3g) x_b=(%.3g,%.3g,%.3g) "
                  "v_a=(%.3g,%.3g,%.3g) v_b=(%.3g,%.3g,%.3g) kd=%.4g",
                  i, s.xa.x(), s.xa.y(), s.xa.z(), s.xb.x(), s.xb.y(), s.xb.z(), s.va.x(), s.va.y(),
                  s.va.z(), s.vb.x(), s.vb.y(), s.vb.z(), s.k);
  else
    std::snprintf(buf, sizeof buf,
                  "random spring #%d: x_a=(%.3g,%.3g,%.3g) x_b=(%.3g,%.3g,%.3g) ks=%.4g rest=%.4g",
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

}  // namespace

// spring_force / damper_force: the student's function on each listed (or random) input; output
// fNN is the force on particle a of input NN.
void register_spring_force_cases(Registry& r) {
  r.add({"spring_force",
         "spring_force on hand-made (params.springs) or random (params.random) springs", nullptr,
         [](const TaskTable& t, const Params& p, const Json&, Outputs& o) {
           run_springs(t, inputs(p, false), o);
         }});
  r.add({"damper_force",
         "damper_force on hand-made (params.dampers) or random (params.random) dampers", nullptr,
         [](const TaskTable& t, const Params& p, const Json&, Outputs& o) {
           run_dampers(t, inputs(p, true), o);
         }});
}

// ----- the course integrators -----

namespace {

const IntegratorMethod kMethods[] = {
    {"explicit_euler", "explicit_euler_step", &TaskTable::explicit_euler_step},
    {"implicit_euler", "implicit_euler_step", &TaskTable::implicit_euler_step},
    {"midpoint", "midpoint_step", &TaskTable::midpoint_step},
    {"rk4", "rk4_step", &TaskTable::rk4_step},
};

// Free fall of three particles (physics contract §9): params.steps steps of params.h from start.
void run_free_fall(const TaskTable& t, const Params& params, const FreeFallStart& start,
                   Outputs& out) {
  const IntegratorMethod& m = integrator_method(params);
  const double h = params.number("h");
  const long steps = params.integer("steps");
  FreeFallSystem system(3, Vec3(0.0, -9.8, 0.0));
  State s;
  s.resize(3);
  s.x = start.x;
  s.v = start.v;
  step_n(t.*(m.member), system, s, h, steps);
  char what[64];
  std::snprintf(what, sizeof what, "after %ld steps of %g s of ", steps, h);
  out.value("y0", s.x(1, 0), std::string("height ") + what + start.dropped + " [m]");
  out.array("x", s.x, "positions of three falling particles at the end [m]");
  out.array("v", s.v, "velocities of three falling particles at the end [m/s]");
}

// Observed order on the linear two-particle spring, damping params.damping, one run to t = 1 s
// per step size in params.h (at least two).
void run_convergence(const TaskTable& t, const Params& params, Outputs& out) {
  const IntegratorMethod& m = integrator_method(params);
  const double damping = params.number("damping");
  std::vector<double> hs = params.numbers("h");
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

}  // namespace

const IntegratorMethod& integrator_method(const Params& params) {
  const std::string key = params.text("method");
  for (const IntegratorMethod& m : kMethods)
    if (key == m.key) return m;
  throw std::runtime_error(
      "params.method: expected explicit_euler, implicit_euler, midpoint or rk4, got " + key);
}

void step_n(StepFunction fn, System& system, State& s, double h, long n) {
  Workspace w;
  for (long i = 0; i < n; ++i) {
    w.resize(system.particle_count());
    fn(system, s, h, w);
  }
}

void register_integrator_free_fall(Registry& r, const FreeFallStart& start) {
  r.add({"integrator_free_fall", "one integrator on three particles in free fall", nullptr,
         [start](const TaskTable& t, const Params& p, const Json&, Outputs& o) {
           run_free_fall(t, p, start, o);
         }});
}

void register_integrator_convergence(Registry& r) {
  r.add({"integrator_convergence", "one integrator's order of accuracy on the two-particle spring",
         nullptr, [](const TaskTable& t, const Params& p, const Json&, Outputs& o) {
           run_convergence(t, p, o);
         }});
}

}  // namespace jelly::grade
