// The informational course scenes: ALL of the student's code together (their grid builders,
// spring and damper forces, cloth–sphere and sphere–sphere impulses, friction when μ > 0 and one
// of their integrators) on a course cloth scene for a short time. The scene is built from the
// case's parameters through the World's cloth API (cloth contract §1–§5), so every input is in
// the case file. Outputs: whether the run finished without the stability detector firing, the
// cloth's centre of mass over time (the report plots its height against the reference's), the
// spheres' final centres, the lowest particle and the pins (bitwise put).
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cases.hpp"
#include "jelly/cloth_physics.hpp"
#include "jelly/integrator.hpp"
#include "jelly/simulator.hpp"

namespace jelly::grade {

namespace {

// params.cloth (n, size, mass, center, pins = [[i, k], ...]; "corners" when pins is absent),
// params.springs = { ks, kd }, params.air_drag, params.gravity, params.spheres = [{ center,
// radius, kinematic, mass?, velocity?, schedule = [{ time, velocity }] }], params.collisions =
// { cloth_restitution, sphere_restitution, tolerance, friction, push_out }.
std::unique_ptr<World> course_world(const TaskTable& tasks, const Params& params) {
  auto world = std::make_unique<World>(tasks);
  const Params c = params.table("cloth");
  ClothSpec spec = cloth_from_params(c);
  spec.mass = c.number("mass", spec.mass);
  if (!c.has("pins")) spec.pin_sets = {"corners"};
  spec.air_drag = params.number("air_drag", 0.0);
  const int cloth = cloth_physics(*world).add_cloth(spec);
  const Params springs = params.table("springs");
  for (SpringType type : {SpringType::Structural, SpringType::Shear, SpringType::Bending})
    cloth_physics(*world).build_cloth_springs(cloth, type, springs.number("ks"),
                                              springs.number("kd"));
  for (const Params& p : params.list("spheres")) {
    SphereSpec s;
    s.center = p.vec("center");
    s.radius = p.number("radius");
    s.kinematic = p.integer("kinematic", 0) != 0;
    if (p.has("mass")) s.mass = p.number("mass");
    s.velocity = p.vec("velocity", Vec3::Zero());
    if (p.has("schedule"))
      for (const Params& e : p.list("schedule"))
        s.schedule.push_back({e.number("time"), e.vec("velocity")});
    cloth_physics(*world).add_sphere(s);
  }
  const Params k = params.table("collisions");
  ClothCollisionSettings settings;
  settings.cloth_restitution = k.number("cloth_restitution");
  settings.sphere_restitution = k.number("sphere_restitution");
  settings.tolerance = k.number("tolerance");
  settings.friction = k.number("friction", 0.0);
  settings.push_out = k.number("push_out", 0.0);
  cloth_physics(*world).set_cloth_collisions(settings);
  world->set_gravity(params.vec("gravity"));
  return world;
}

void run_course_cloth(const TaskTable& tasks, const Params& params, Outputs& out) {
  const std::string method = params.text("integrator");
  const std::optional<IntegratorKind> kind = integrator_from_string(method);
  if (!kind || *kind == IntegratorKind::SymplecticEuler || *kind == IntegratorKind::BackwardEuler)
    throw std::runtime_error(
        "params.integrator: expected explicit_euler, implicit_euler, midpoint or rk4, got " +
        method);
  const double h = params.number("h");
  Simulator::Options o(*kind, h);
  o.detect_instability = true;
  Simulator sim(course_world(tasks, params), o);
  const World& world = sim.world();
  const Eigen::Index cloth_n = cloth_physics(world).cloth_particle_count();
  const Vec3Array start = sim.state().x;
  const double duration = params.number("duration");
  const long every = params.integer("sample_every");
  const long steps = std::lround(duration / h);
  std::vector<double> t, cy, cx, cz;
  double lowest = INFINITY, first_impulse = -1.0;
  // Frames for the report (params.frame_times, optional): at the first step at or after each
  // time, every particle of the state (the cloth's, then the dynamic spheres') and then every
  // kinematic sphere's centre in scene order, as `jelly render --replay` reads a cloth scene.
  const std::vector<double> frame_at =
      params.has("frame_times") ? params.numbers("frame_times") : std::vector<double>{};
  std::vector<double> frame_times, frame_positions;
  std::size_t next_frame = 0;
  const auto record_frames = [&]() {
    for (; next_frame < frame_at.size() && sim.time() + 0.5 * h >= frame_at[next_frame];
         ++next_frame) {
      const Vec3Array& x = sim.state().x;
      frame_times.push_back(sim.time());
      frame_positions.insert(frame_positions.end(), x.data(), x.data() + x.size());
      for (int i = 0; i < cloth_physics(world).sphere_count(); ++i)
        if (cloth_physics(world).sphere_is_kinematic(i)) {
          const Vec3 c = cloth_physics(world).sphere(i).center;
          frame_positions.insert(frame_positions.end(), c.data(), c.data() + 3);
        }
    }
  };
  record_frames();
  for (long k = 1; k <= steps; ++k) {
    if (sim.step() != StepResult::Ok) break;
    record_frames();
    if (first_impulse < 0.0 && world.counters().impulses > 0) first_impulse = sim.time();
    if (k % every == 0) {
      const Vec3Array& x = sim.state().x;
      const Vec3 com = x.leftCols(cloth_n).rowwise().mean();
      t.push_back(sim.time());
      cx.push_back(com.x());
      cy.push_back(com.y());
      cz.push_back(com.z());
      lowest = std::min(lowest, x.row(1).leftCols(cloth_n).minCoeff());
    }
  }
  const bool unstable = sim.instability().has_value();
  char what[120];
  std::snprintf(what, sizeof what, "%g s of the scene with your %s_step (h = %g s)", duration,
                method.c_str(), h);
  out.value(
      "finished", unstable ? 0.0 : 1.0,
      std::string("the run lasted ") + what + " without the stability detector firing (1 yes)");
  out.values("com_time", t, "times of the centre-of-mass samples [s]");
  out.values("com_y", cy, "the cloth's centre-of-mass height over time [m]");
  out.values("com_x", cx, "the cloth's centre-of-mass x over time [m]");
  out.values("com_z", cz, "the cloth's centre-of-mass z over time [m]");
  const Vec3Array& x = sim.state().x;
  out.vec("final_com", x.leftCols(cloth_n).rowwise().mean(),
          std::string("the cloth's centre of mass after ") + what + " [m]");
  out.value("first_impulse_time", first_impulse,
            "time of the first collision impulse (cloth–sphere or sphere–sphere) [s]");
  out.value("impulses", static_cast<double>(world.counters().impulses),
            std::string("number of collision impulses applied during ") + what);
  out.value("lowest_y", lowest, std::string("the lowest cloth particle during ") + what + " [m]");
  for (int i = 0; i < cloth_physics(world).sphere_count(); ++i)
    out.vec("sphere" + std::to_string(i) + "_center", cloth_physics(world).sphere(i).center,
            "centre of sphere " + std::to_string(i) + " (scene order) after " + what + " [m]");
  int moved = 0;
  for (Eigen::Index i = 0; i < cloth_n; ++i)
    if (cloth_physics(world).is_pinned(static_cast<int>(i)) &&
        !(x.col(i).array() == start.col(i).array()).all())
      ++moved;
  out.value("pinned_moved", moved,
            std::string("pinned particles not bitwise where they started after ") + what);
  out.value(
      "final_kinetic_energy", sim.energy().kinetic,
      std::string("kinetic energy of the cloth and the dynamic spheres after ") + what + " [J]");
  if (!frame_at.empty()) {
    out.values("frame_times", frame_times,
               "times of the recorded frames [s] (for the report, not graded)");
    out.values("frame_positions", frame_positions,
               "every particle's x, y, z at each recorded frame, then each kinematic sphere's "
               "centre, frame after frame [m] (for the report, not graded)");
  }
}

}  // namespace

// course_cloth: params.integrator (explicit_euler, implicit_euler, midpoint, rk4), params.h,
// params.duration [s], the cloth's centre of mass sampled every params.sample_every steps,
// positions recorded at params.frame_times [s] (optional), and the scene as course_world reads it.
void register_scene_cases(Registry& r) {
  r.add({"course_cloth",
         "a course cloth scene for a short time with all of your code (informational)", nullptr,
         [](const TaskTable& t, const Params& p, const Json&, Outputs& o) {
           run_course_cloth(t, p, o);
         }});
}

}  // namespace jelly::grade
