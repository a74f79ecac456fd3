// A2.T8–T11 cases: each course integrator stepped on framework-provided systems only (free fall,
// the linear two-particle spring, and a small cloth linearised about its rest shape with some of
// its particles pinned, inverse mass 0): no student force, spring or collision code runs, so a
// wrong spring sign cannot fail an integrator test. The pinned cloth also proves that a pin stays
// bitwise where it was under the student's integrator (cloth contract §1, §7). Free fall and
// convergence are the mass_spring module's slot-level cases (grader/runner/mass_spring_cases.cpp);
// the cloth's are A2's own.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "cases.hpp"
#include "jelly/cloth_tasks.hpp"
#include "jelly/test_systems.hpp"
#include "jelly/world.hpp"
#include "mass_spring_cases.hpp"

namespace jelly::grade {

namespace {

// The free fall's start (the mass_spring module's integrator_free_fall): three particles, the
// first a cloth particle dropped from rest at y = 1 m (physics contract §9, which the cloth keeps:
// cloth contract §7).
FreeFallStart a2_free_fall() {
  FreeFallStart start{Vec3Array(3, 3), Vec3Array(3, 3),
                      "a cloth particle dropped from rest at y = 1 m"};
  start.x << -2.0, 0.0, 2.0, 1.0, 1.0, 1.0, 0.0, 0.5, -0.5;
  start.v << 0.0, 0.5, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0;
  return start;
}

// prepare(): the REFERENCE springs of the cloth params.cloth, per type, into input["springs"].
void prepare_cloth_springs(const TaskTable& reference, const Params& params, Json& input) {
  const ClothGrid cloth(cloth_from_params(params.table("cloth")), 0);
  std::vector<Spring> structural, shear, bending;
  cloth_tasks(reference).add_grid_structural_springs(cloth, structural);
  cloth_tasks(reference).add_grid_shear_springs(cloth, shear);
  cloth_tasks(reference).add_grid_bending_springs(cloth, bending);
  input["springs"] = {{"structural", springs_to_json(structural)},
                      {"shear", springs_to_json(shear)},
                      {"bending", springs_to_json(bending)}};
}

// A System whose pinned particles have inverse mass 0: their acceleration is exactly zero
// (cloth contract decision 3), whatever the linear springs would give them.
class PinnedSystem : public System {
 public:
  PinnedSystem(std::unique_ptr<LinearSystem> inner, std::vector<int> pinned)
      : inner_(std::move(inner)), pinned_(std::move(pinned)) {}
  void acceleration(const State& s, Vec3Array& a) override {
    inner_->acceleration(s, a);
    for (int p : pinned_) a.col(p).setZero();
  }
  Eigen::Index particle_count() const override { return inner_->particle_count(); }

 private:
  std::unique_ptr<LinearSystem> inner_;
  std::vector<int> pinned_;
};

// The cloth params.cloth (pins = [[i, k], ...]) with the prepared reference springs, stiffness
// params.ks, dampers params.kd, gravity params.gravity, linearised about its rest shape; its
// state perturbed by params.dx·U (positions) and params.dv·U (velocities) except at the pins;
// params.steps steps (default 1) of params.h with the student's integrator.
void run_cloth_steps(const TaskTable& t, const Params& params, const Json& input, Outputs& out) {
  const IntegratorMethod& m = integrator_method(params);
  const double h = params.number("h");
  const long steps = params.integer("steps", 1);
  const ClothSpec spec = cloth_from_params(params.table("cloth"));
  const ClothGrid cloth(spec, 0);
  World world{TaskTable{}};
  const Vec3Array rest = cloth.initial_positions();
  world.add_particles(rest, Vec3Array::Zero(3, rest.cols()), 1.0);
  const std::pair<const char*, SpringType> types[] = {{"structural", SpringType::Structural},
                                                      {"shear", SpringType::Shear},
                                                      {"bending", SpringType::Bending}};
  for (const auto& [key, type] : types) {
    SpringGroup g;
    g.type = type;
    g.ks = params.number("ks");
    g.kd = params.number("kd");
    g.degenerate_length = degenerate_length_for(cloth.spacing());
    g.springs = springs_from_json(input.at("springs").at(key));
    world.add_spring_group(std::move(g));
  }
  world.set_gravity(params.vec("gravity", Vec3::Zero()));
  std::vector<int> pins;
  for (const GridCoord& p : spec.pins) pins.push_back(cloth.index(p[0], p[1]));
  PinnedSystem system(std::make_unique<LinearSystem>(world, rest), pins);
  State s;
  s.resize(rest.cols());
  s.x = rest;
  s.v.setZero();
  Sequence r(static_cast<std::uint64_t>(params.integer("seed")));
  const double dx = params.number("dx"), dv = params.number("dv");
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    const Vec3 ddx = dx * r.next3();
    const Vec3 ddv = dv * r.next3();
    if (std::find(pins.begin(), pins.end(), static_cast<int>(i)) != pins.end()) continue;
    s.x.col(i) += ddx;
    s.v.col(i) = ddv;
  }
  const State start = s;
  step_n(t.*(m.member), system, s, h, steps);
  char what[160];
  std::snprintf(what, sizeof what,
                "after %ld step(s) of h = %g s of a damped linear %d×%d cloth with %zu pinned "
                "particles",
                steps, h, spec.n, spec.n, pins.size());
  out.array("x", s.x, std::string("positions ") + what + " [m]");
  out.array("v", s.v, std::string("velocities ") + what + " [m/s]");
  // A pin's position and velocity must be bitwise what they were: x + h·0 is x.
  int moved = 0;
  std::string text;
  for (std::size_t k = 0; k < pins.size(); ++k) {
    const int p = pins[k];
    const bool same = (s.x.col(p).array() == start.x.col(p).array()).all() &&
                      (s.v.col(p).array() == start.v.col(p).array()).all();
    if (!same && moved++ < 2) {
      char b[200];
      std::snprintf(b, sizeof b, "%spinned particle %s moved by %.3g m", text.empty() ? "" : "; ",
                    grid_name(spec.pins[k][0], spec.pins[k][1]).c_str(),
                    (s.x.col(p) - start.x.col(p)).norm());
      text += b;
    }
  }
  out.value("pinned_moved", moved,
            std::string("pinned particles (inverse mass 0, acceleration 0) not bitwise where ") +
                "they started " + what);
  out.detail("pinned_moved", "", moved > 0 ? "yours: " + text : "");
}

}  // namespace

// Every generator takes params.method (explicit_euler, implicit_euler, midpoint, rk4).
void register_integrator_cases(Registry& r) {
  register_integrator_free_fall(r, a2_free_fall());
  register_integrator_convergence(r);
  r.add({"integrator_cloth_steps",
         "steps of one integrator on a damped linear cloth with pinned particles",
         &prepare_cloth_springs,
         [](const TaskTable& t, const Params& p, const Json& in, Outputs& o) {
           run_cloth_steps(t, p, in, o);
         }});
}

}  // namespace jelly::grade
