// A2.T4–T5 cases: spring_force and damper_force (the same functions and signatures as A1's, cloth
// contract §2 = physics contract §2) on hand-made springs, degenerate lengths included, and on
// random ones. The cloth's own springs are exercised by the course scene.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "cases.hpp"
#include "jelly/spring.hpp"

namespace jelly::grade {

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
void register_force_cases(Registry& r) {
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

}  // namespace jelly::grade
