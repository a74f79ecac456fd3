// A1.T6–T9 generators: the four terrain functions on hand-made particles (their positions,
// velocities and forces are case parameters), and particle clouds without springs (framework
// symplectic Euler) in which only the task under test acts: collision scenes have contact off,
// contact scenes have collision off.
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

#include <Eigen/Geometry>

#include "cases.hpp"
#include "jelly/integrator.hpp"
#include "jelly/scene.hpp"
#include "jelly/world.hpp"

namespace jelly::grade {

namespace {

// A terrain from params: { preset = NAME } with optional overrides hole_center, hole_radius (a
// plane gets a hole), restitution, friction.
Terrain terrain_from_params(const Params& p) {
  const std::string name = p.text("preset");
  std::optional<Terrain> t = terrain_preset(name);
  if (!t) throw std::runtime_error("params.terrain.preset: unknown terrain preset '" + name + "'");
  std::visit(
      [&](auto& shape) {
        if (p.has("restitution")) shape.surface.restitution = p.number("restitution");
        if (p.has("friction")) shape.surface.friction = p.number("friction");
        if constexpr (std::is_same_v<std::decay_t<decltype(shape)>, Plane>) {
          if (p.has("hole_center") || p.has("hole_radius")) {
            shape.has_hole = true;
            shape.hole_center = p.vec("hole_center", shape.hole_center);
            shape.hole_radius = p.number("hole_radius", shape.hole_radius);
          }
        }
      },
      t->shape);
  return *t;
}

enum class Fn { CollidePlane, CollideBowl, ContactPlane, ContactBowl };

Fn function_named(const std::string& name) {
  if (name == "collide_plane") return Fn::CollidePlane;
  if (name == "collide_bowl") return Fn::CollideBowl;
  if (name == "contact_plane") return Fn::ContactPlane;
  if (name == "contact_bowl") return Fn::ContactBowl;
  throw std::runtime_error(
      "params.function: expected collide_plane, collide_bowl, contact_plane or contact_bowl, got " +
      name);
}

// params.function on params.terrain for every probe of params.probes (label, x, v, f): each case
// mixes particles that must respond and ones that must not, so code that does nothing fails it.
void run_probes(const TaskTable& t, const Params& params, Outputs& out) {
  const Fn fn = function_named(params.text("function"));
  const bool plane = fn == Fn::CollidePlane || fn == Fn::ContactPlane;
  const Terrain terrain = terrain_from_params(params.table("terrain"));
  if (plane != std::holds_alternative<Plane>(terrain.shape))
    throw std::runtime_error("params.terrain: " + params.text("function") + " needs a " +
                             (plane ? "plane" : "bowl"));
  const std::vector<Params> probes = params.list("probes");
  for (std::size_t i = 0; i < probes.size(); ++i) {
    const Params& p = probes[i];
    const std::string label = p.text("label");
    const Vec3 x = p.vec("x"), v0 = p.vec("v"), f0 = p.vec("f");
    char name[24];
    std::snprintf(name, sizeof name, "%02zu", i);
    bool hit = false;
    if (fn == Fn::CollidePlane || fn == Fn::CollideBowl) {
      Vec3 v = v0;
      hit = plane ? t.collide_plane(std::get<Plane>(terrain.shape), x, v)
                  : t.collide_bowl(std::get<Bowl>(terrain.shape), x, v);
      out.value(std::string("hit") + name, hit ? 1.0 : 0.0,
                "collided? (1 yes, 0 no) for a particle " + label);
      out.vec(std::string("v") + name, v, "velocity after the response for a particle " + label);
    } else {
      Vec3 f = f0;
      hit = plane ? t.contact_plane(std::get<Plane>(terrain.shape), x, v0, f)
                  : t.contact_bowl(std::get<Bowl>(terrain.shape), x, v0, f);
      out.value(std::string("hit") + name, hit ? 1.0 : 0.0,
                "in contact? (1 yes, 0 no) for a particle " + label);
      out.vec(std::string("f") + name, f,
              "force after contact and friction for a particle " + label);
    }
  }
}

// Initial particles of a cloud, from params.placement (U uniform in [−1, 1), drawn in the order
// written):
//   mode "drop":        x = center + (half.x·U, 0, half.z·U) + (0, half.y·U, 0), v = velocity ⊙ (U,
//   U, U) mode "slide_plane": x = (center.x + half.x·U, center.y, center.z + half.z·U), v =
//   (velocity.x·U, 0, velocity.z·U) mode "slide_bowl":  on the bowl's sphere at height height +
//   height_jitter·U, at angle angle·U
//                       about the vertical axis, moving along the horizontal tangent at speed·U
void place_cloud(const Params& pl, const Terrain& terrain, Sequence& r, Vec3Array& x,
                 Vec3Array& v) {
  const std::string mode = pl.text("mode");
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    if (mode == "drop") {
      const Vec3 c = pl.vec("center"), half = pl.vec("half"), vel = pl.vec("velocity");
      // Draws in the order of the reference data (z before x: Sequence::next3).
      const double uz = r.next(), ux = r.next();
      const Vec3 base(c.x() + half.x() * ux, c.y(), c.z() + half.z() * uz);
      x.col(i) = base + Vec3(0.0, half.y() * r.next(), 0.0);
      v.col(i) = vel.cwiseProduct(r.next3());
    } else if (mode == "slide_plane") {
      const Vec3 c = pl.vec("center"), half = pl.vec("half"), vel = pl.vec("velocity");
      const double uz = r.next(), ux = r.next();
      x.col(i) = Vec3(c.x() + half.x() * ux, c.y(), c.z() + half.z() * uz);
      const double wz = r.next(), wx = r.next();
      v.col(i) = Vec3(vel.x() * wx, 0.0, vel.z() * wz);
    } else if (mode == "slide_bowl") {
      if (!std::holds_alternative<Bowl>(terrain.shape))
        throw std::runtime_error("params.placement.mode: slide_bowl needs a bowl terrain");
      const Bowl& b = std::get<Bowl>(terrain.shape);
      const double y = pl.number("height") + pl.number("height_jitter") * r.next();
      const double dy = y - b.center.y();
      const double hr = std::sqrt(b.radius * b.radius - dy * dy);
      const double a = pl.number("angle") * r.next();
      x.col(i) = b.center + Vec3(hr * std::cos(a), dy, hr * std::sin(a));
      const Vec3 nrm = (b.center - Vec3(x.col(i))).normalized();
      Vec3 tangent = nrm.cross(Vec3(0, 1, 0));
      if (tangent.norm() < 1e-9) tangent = Vec3(1, 0, 0);
      v.col(i) = pl.number("speed") * r.next() * tangent.normalized();
    } else {
      throw std::runtime_error(
          "params.placement.mode: expected drop, slide_plane or slide_bowl, got " + mode);
    }
  }
}

// A cloud of params.count free particles (no springs, mass 1 kg), gravity, one terrain
// (params.terrain) with only params.response ("collision" or "contact") on, the framework's
// collision pass and symplectic Euler: params.steps steps of params.h, positions every
// params.sample_every steps.
void run_cloud(const TaskTable& tasks, const Params& params, Outputs& out) {
  World world(tasks);
  Sequence r(static_cast<std::uint64_t>(params.integer("seed")));
  const long n = params.integer("count");
  const std::string response = params.text("response");
  if (response != "collision" && response != "contact")
    throw std::runtime_error("params.response: expected collision or contact, got " + response);
  const bool collision = response == "collision";
  Terrain t = terrain_from_params(params.table("terrain"));
  const bool bowl = std::holds_alternative<Bowl>(t.shape);
  Vec3Array x(3, n), v(3, n);
  place_cloud(params.table("placement"), t, r, x, v);
  world.add_particles(x, v, 1.0);
  world.set_gravity(Vec3(0.0, -9.8, 0.0));
  t.collision = collision;
  t.contact = !collision;
  world.add_terrain(t);
  State& s = world.state();
  Workspace w;
  w.resize(s.size());
  const double h = params.number("h");
  const long steps = params.integer("steps"), every = params.integer("sample_every");
  const std::string fn = collision ? std::string(bowl ? "collide_bowl" : "collide_plane")
                                   : std::string(bowl ? "contact_bowl" : "contact_plane");
  for (long step = 1; step <= steps; ++step) {
    world.apply_collisions(s);
    symplectic_euler_step(world, s, h, w);
    if (step % every == 0) {
      char what[160];
      std::snprintf(
          what, sizeof what,
          "positions of the %ld particles at t = %g s (framework symplectic Euler; only your ", n,
          static_cast<double>(step) * h);
      out.array("x_t" + std::to_string(step), s.x, std::string(what) + fn + " acts on them) [m]");
    }
  }
}

}  // namespace

void register_terrain_cases(Registry& r) {
  r.add(
      {"terrain_probes", "one terrain function on hand-made particles (params.probes)", nullptr,
       [](const TaskTable& t, const Params& p, const Json&, Outputs& o) { run_probes(t, p, o); }});
  r.add({"particle_cloud", "free particles over one terrain with only collision or only contact",
         nullptr,
         [](const TaskTable& t, const Params& p, const Json&, Outputs& o) { run_cloud(t, p, o); }});
}

}  // namespace jelly::grade
