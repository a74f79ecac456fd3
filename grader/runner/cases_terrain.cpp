// A1.T6–T9 cases: the four terrain functions on hand-made particles at and around every boundary
// (ε, the hole's edge, the bowl's rim, moving in and out, a tilted plane), and particle clouds
// without springs (framework symplectic Euler) in which only the task under test acts: collision
// scenes have contact off, contact scenes have collision off.
#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>

#include "harness.hpp"
#include "jelly/integrator.hpp"
#include "jelly/scene.hpp"
#include "jelly/world.hpp"

namespace jelly::grade {

namespace {

Plane course_floor() { return std::get<Plane>(terrain_preset("course-2023-floor")->shape); }
Bowl course_bowl() { return std::get<Bowl>(terrain_preset("course-2023-bowl")->shape); }

// A tilted plane (normal (1,1,0)/√2 through (0,−1,0)) with a hole of radius 1 around (1,−2,0).
Plane tilted_plane() {
  Plane p = std::get<Plane>(terrain_preset("course-2021-tilted")->shape);
  p.has_hole = true;
  p.hole_center = Vec3(1.0, -2.0, 0.0);
  p.hole_radius = 1.0;
  p.surface.restitution = 0.5;
  return p;
}

struct Probe {
  std::string group;  // each group is one case and mixes "must respond" and "must not respond"
  std::string label;
  int surface;  // 0 course floor, 1 tilted plane (plane tasks); 0 course bowl (bowl tasks)
  Vec3 x, v, f;
};

// Points of the floor/hole geometry.
Vec3 hole_point(double distance, double y) {
  const Plane p = course_floor();
  return p.hole_center + Vec3(-distance, y, 0.0);  // towards −x from the hole centre
}

std::vector<Probe> plane_probes() {
  const Plane fl = course_floor();
  const Plane tp = tilted_plane();
  const double r = fl.hole_radius;
  const Vec3 g(0.0, -9.8, 0.0);
  const Vec3 t1 = Vec3(1.0, -1.0, 0.0).normalized();  // a tangent of the tilted plane
  return {
      {"eps", "high above the floor (φ = 0.5 m), falling", 0, {-8, 0.5, 0}, {0.3, -2, 0.1}, g},
      {"eps", "just inside ε (φ = 0.0099 m), falling", 0, {-8, 0.0099, 0}, {0, -2, 0}, g},
      {"eps", "just outside ε (φ = 0.0101 m), falling", 0, {-8, 0.0101, 0}, {0, -2, 0}, g},
      {"eps", "on the floor (φ = 0), falling at an angle", 0, {-8, 0.0, 1}, {3, -2, 1}, g},
      {"eps", "below the floor (φ = −0.05 m), falling", 0, {-8, -0.05, 0}, {0.5, -1, 0}, g},
      {"eps", "below the floor, already moving up", 0, {-8, -0.05, 0}, {0.5, 1, 0}, g},
      {"eps", "on the floor, sliding (N·v = 0)", 0, {-8, 0.0, 0}, {1, 0, 0.5}, g},
      {"eps", "on the floor, moving up slowly (N·v = 0.005 < ε)", 0, {-8, 0.0, 0}, {1, 0.005, 0}, g},
      {"eps", "on the floor, moving up (N·v = 0.02 > ε)", 0, {-8, 0.0, 0}, {1, 0.02, 0}, g},
      {"eps", "on the floor, pushed up by the springs (N·f > 0)", 0, {-8, 0.0, 0}, {1, 0, 0}, {0, 5, 0}},
      {"hole", "over the middle of the hole (falls through)", 0, hole_point(3.0, 0.005), {0, -2, 0}, g},
      {"hole", "just inside the hole's edge (r_h − 1e-6)", 0, hole_point(r - 1e-6, 0.005), {0.2, -2, 0}, g},
      {"hole", "just outside the hole's edge (r_h + 1e-6)", 0, hole_point(r + 1e-6, 0.005), {0.2, -2, 0}, g},
      {"hole", "in the hole, far below the floor", 0, hole_point(2.0, -3.0), {0, -2, 0}, g},
      {"tilted", "tilted plane: on it, moving in at an angle", 1, tp.point + 3.0 * Vec3(0, 0, 1) - 2.0 * t1, {-1, -2, 0.5}, g},
      {"tilted", "tilted plane: behind it (φ = −0.1), moving in", 1, tp.point + Vec3(0, 0, 2) - 0.1 * tp.normal, {-1, 0, 0}, g},
      {"tilted", "tilted plane: outside the hole measured in the plane (1.2 r_h), inside it measured in x–z",
       1, tp.hole_center + 1.2 * t1 + 0.005 * tp.normal, {-1, -1, 0}, g},
      {"tilted", "tilted plane: inside the hole measured in the plane (0.9 r_h)", 1,
       tp.hole_center + 0.9 * Vec3(0, 0, 1) + 0.005 * tp.normal, {-1, -1, 0}, g},
  };
}

// A point on the bowl's sphere at height y (towards +x from the axis) moved by `inward` along N.
Vec3 bowl_wall(double y, double inward) {
  const Bowl b = course_bowl();
  const double dy = y - b.center.y();
  const double horizontal = std::sqrt(b.radius * b.radius - dy * dy);
  const Vec3 on = b.center + Vec3(horizontal, dy, 0.0);
  return on + inward * (b.center - on).normalized();
}

std::vector<Probe> bowl_probes() {
  const Bowl b = course_bowl();
  const Vec3 g(0.0, -9.8, 0.0);
  const Vec3 bottom = b.center - Vec3(0, b.radius, 0);
  const double rr = b.rim_radius();
  return {
      {"eps", "at the bottom (φ = 0.005), falling at an angle", 0, bottom + Vec3(0, 0.005, 0), {0.5, -2, 0.2}, g},
      {"eps", "at the bottom, moving up", 0, bottom + Vec3(0, 0.005, 0), {0.5, 2, 0}, g},
      {"eps", "well inside the bowl (φ = 2 m), falling", 0, bottom + Vec3(0, 2, 0), {0, -2, 0}, g},
      {"eps", "just inside ε at the bottom (φ = 0.0099)", 0, bottom + Vec3(0, 0.0099, 0), {0, -2, 0}, g},
      {"eps", "just outside ε at the bottom (φ = 0.0101)", 0, bottom + Vec3(0, 0.0101, 0), {0, -2, 0}, g},
      {"wall", "on the wall halfway up, moving into it", 0, bowl_wall(-1.0, 0.0), {2, -1, 0.3}, g},
      {"wall", "behind the wall (φ = −0.05), moving into it", 0, bowl_wall(-1.5, -0.05), {1, -1, 0}, g},
      {"wall", "on the wall, sliding along it", 0, bowl_wall(-1.0, 0.0), {0, 0, 1}, g},
      {"rim", "at the rim inside (just below y_rim, 1e-6 inside the rim radius)", 0,
       b.center + Vec3(rr - 1e-6, -b.center.y() - 1e-4, 0), {1, -0.5, 0}, g},
      {"rim", "on the floor around the hole, beyond the rim radius (r_rim + 0.5)", 0,
       b.center + Vec3(rr + 0.5, -b.center.y(), 0), {0.3, -1, 0}, g},
      {"rim", "just beyond the rim radius (r_rim + 1e-6), at the rim height", 0,
       b.center + Vec3(rr + 1e-6, -b.center.y(), 0), {1, -0.5, 0}, g},
      {"rim", "above the rim by more than ε, outside the sphere's top", 0, b.center + Vec3(0, b.radius + 0.5, 0), {0, 1, 0}, g},
      {"rim", "at the bowl sphere's centre (no normal): no response, never NaN", 0, b.center, {0, -1, 0}, g},
      {"eps", "at the bottom, pushed up by the springs (N·f > 0)", 0, bottom + Vec3(0, 0.005, 0), {1, 0, 0}, {0, 5, 0}},
      {"eps", "at the bottom, moving up slowly (N·v = 0.005 < ε)", 0, bottom, {1, 0.005, 0}, g},
  };
}

enum class Fn { CollidePlane, CollideBowl, ContactPlane, ContactBowl };

void run_probes(const TaskTable& t, Fn fn, const std::string& group, Outputs& out) {
  const bool plane = fn == Fn::CollidePlane || fn == Fn::ContactPlane;
  std::vector<Probe> probes;
  for (const Probe& p : plane ? plane_probes() : bowl_probes())
    if (p.group == group) probes.push_back(p);
  const Plane planes[2] = {course_floor(), tilted_plane()};
  const Bowl bowl = course_bowl();
  for (std::size_t i = 0; i < probes.size(); ++i) {
    const Probe& p = probes[i];
    char name[24];
    std::snprintf(name, sizeof name, "%02zu", i);
    bool hit = false;
    if (fn == Fn::CollidePlane || fn == Fn::CollideBowl) {
      Vec3 v = p.v;
      hit = fn == Fn::CollidePlane ? t.collide_plane(planes[p.surface], p.x, v) : t.collide_bowl(bowl, p.x, v);
      out.value(std::string("hit") + name, hit ? 1.0 : 0.0, "collided? (1 yes, 0 no) for a particle " + p.label);
      out.vec(std::string("v") + name, v, "velocity after the response for a particle " + p.label);
    } else {
      Vec3 f = p.f;
      hit = fn == Fn::ContactPlane ? t.contact_plane(planes[p.surface], p.x, p.v, f)
                                   : t.contact_bowl(bowl, p.x, p.v, f);
      out.value(std::string("hit") + name, hit ? 1.0 : 0.0, "in contact? (1 yes, 0 no) for a particle " + p.label);
      out.vec(std::string("f") + name, f, "force after contact and friction for a particle " + p.label);
    }
  }
}

// A cloud of free particles (no springs), gravity, one terrain with only `collision` or only
// `contact`, the framework's collision pass and symplectic Euler at h = 1 ms.
void run_cloud(const TaskTable& tasks, bool bowl, bool collision, Outputs& out) {
  World world(tasks);
  Sequence r(bowl ? 11 : 13);
  const int n = 16;
  Vec3Array x(3, n), v(3, n);
  const Bowl b = course_bowl();
  for (int i = 0; i < n; ++i) {
    if (collision) {
      // Dropped from 0.5–2.5 m above the surface with sideways velocities.
      const Vec3 base = bowl ? Vec3(b.center.x() + 3.0 * r.next(), 0.5, b.center.z() + 3.0 * r.next())
                             : Vec3(2.0 + 9.0 * r.next(), 1.5, 1.0 + 9.0 * r.next());
      x.col(i) = base + Vec3(0.0, 1.0 * r.next(), 0.0);
      v.col(i) = Vec3(1.5 * r.next(), 2.0 * r.next(), 1.5 * r.next());
    } else {
      // Resting on the surface and sliding.
      if (bowl) {
        const double y = -2.0 + 0.6 * r.next();  // the bottom is at y = −2.636
        const double dy = y - b.center.y();
        const double hr = std::sqrt(b.radius * b.radius - dy * dy);
        const double a = 3.14159265358979 * r.next();
        x.col(i) = b.center + Vec3(hr * std::cos(a), dy, hr * std::sin(a));
        const Vec3 nrm = (b.center - Vec3(x.col(i))).normalized();
        Vec3 tangent = nrm.cross(Vec3(0, 1, 0));
        if (tangent.norm() < 1e-9) tangent = Vec3(1, 0, 0);
        v.col(i) = 1.5 * r.next() * tangent.normalized();
      } else {
        x.col(i) = Vec3(-10.0 + 3.0 * r.next(), 0.0, 3.0 * r.next());
        v.col(i) = Vec3(2.0 * r.next(), 0.0, 2.0 * r.next());
      }
    }
  }
  world.add_particles(x, v, 1.0);
  world.set_gravity(Vec3(0.0, -9.8, 0.0));
  Terrain t = *terrain_preset(bowl ? "course-2023-bowl" : "course-2023-floor");
  t.collision = collision;
  t.contact = !collision;
  world.add_terrain(t);
  State& s = world.state();
  Workspace w;
  w.resize(s.size());
  const int steps = collision ? 1500 : 1000;
  for (int step = 1; step <= steps; ++step) {
    world.apply_collisions(s);
    symplectic_euler_step(world, s, 1e-3, w);
    if (step % 250 == 0)
      out.array("x_t" + std::to_string(step), s.x,
                "positions of the 16 particles at t = " + std::to_string(step / 1000.0).substr(0, 4) +
                    " s (framework symplectic Euler; only your " +
                    (collision ? std::string(bowl ? "collide_bowl" : "collide_plane")
                               : std::string(bowl ? "contact_bowl" : "contact_plane")) +
                    " acts on them) [m]");
  }
}

}  // namespace

void register_terrain_cases(Registry& r) {
  auto probe = [](Fn fn, const char* group) {
    const std::string g = group;
    return [fn, g](const TaskTable& t, const Json&, Outputs& o) { run_probes(t, fn, g, o); };
  };
  auto cloud = [](bool bowl, bool collision) {
    return [bowl, collision](const TaskTable& t, const Json&, Outputs& o) { run_cloud(t, bowl, collision, o); };
  };
  struct Group {
    const char* task;
    const char* fn_name;
    Fn fn;
    const char* group;
    const char* what;
  };
  const Group groups[] = {
      {"a1.t6", "collide_plane", Fn::CollidePlane, "eps", "particles above, at and below ε, moving in and out"},
      {"a1.t6", "collide_plane", Fn::CollidePlane, "hole", "particles over the hole and around its edge"},
      {"a1.t6", "collide_plane", Fn::CollidePlane, "tilted", "a tilted plane with a hole"},
      {"a1.t7", "collide_bowl", Fn::CollideBowl, "eps", "particles at the bottom around ε, moving in and out"},
      {"a1.t7", "collide_bowl", Fn::CollideBowl, "wall", "particles on and behind the wall"},
      {"a1.t7", "collide_bowl", Fn::CollideBowl, "rim", "particles around the rim and the floor beyond it"},
      {"a1.t8", "contact_plane", Fn::ContactPlane, "eps", "particles above, at and below ε, moving in and out"},
      {"a1.t8", "contact_plane", Fn::ContactPlane, "hole", "particles over the hole and around its edge"},
      {"a1.t8", "contact_plane", Fn::ContactPlane, "tilted", "a tilted plane with a hole"},
      {"a1.t9", "contact_bowl", Fn::ContactBowl, "eps", "particles at the bottom around ε, moving in and out"},
      {"a1.t9", "contact_bowl", Fn::ContactBowl, "wall", "particles on and behind the wall"},
      {"a1.t9", "contact_bowl", Fn::ContactBowl, "rim", "particles around the rim and the floor beyond it"},
  };
  for (const Group& g : groups)
    r.add({std::string(g.task) + "." + g.fn_name + "." + g.group, std::string(g.fn_name) + ": " + g.what,
           nullptr, probe(g.fn, g.group)});
  r.add({"a1.t6.scene.cloud", "16 particles bouncing on the course floor (collision only)", nullptr, cloud(false, true)});
  r.add({"a1.t7.scene.cloud", "16 particles bouncing in the course bowl (collision only)", nullptr, cloud(true, true)});
  r.add({"a1.t8.scene.cloud", "16 particles sliding on the course floor (contact only)", nullptr, cloud(false, false)});
  r.add({"a1.t9.scene.cloud", "16 particles sliding in the course bowl (contact only)", nullptr, cloud(true, false)});
}

}  // namespace jelly::grade
