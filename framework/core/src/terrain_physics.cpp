// The default physics of a world: a = f/m with gravity, springs and terrain contact, and the
// terrains' collision response (contract §5, §6). Moved from world.cpp as it was.
#include "jelly/terrain_physics.hpp"

#include <cstdint>

#include <algorithm>
#include <optional>
#include <vector>

#include "jelly/terrain_geometry.hpp"
#include "jelly/world.hpp"

namespace jelly {

namespace {

// The sphere obstacle seen from particle x: its tangent plane there (the student's plane functions
// then do the rest). Returns false when x is at the centre (no direction).
bool tangent_plane(const Sphere& s, const Vec3& x, Plane& out) {
  const Vec3 d = x - s.center;
  const double len = d.norm();
  if (!(len > 0.0)) return false;
  out.normal = d / len;
  out.point = s.center + s.radius * out.normal;
  out.has_hole = false;
  out.surface = s.surface;
  return true;
}

// The per-shape loop of collision and contact, written once: calls on_plane(plane, i) or
// on_bowl(bowl, i) for every particle i of x, for a sphere on_plane(its tangent plane at x_i, i)
// (no call at its centre), and returns how many calls returned true. The shape is chosen once per
// pass, not per particle.
template <typename OnPlane, typename OnBowl>
std::int64_t count_per_particle(const Terrain& terrain, const Vec3Array& x, OnPlane on_plane,
                                OnBowl on_bowl) {
  const Eigen::Index n = x.cols();
  std::int64_t hits = 0;
  if (const auto* plane = std::get_if<Plane>(&terrain.shape)) {
    for (Eigen::Index i = 0; i < n; ++i)
      if (on_plane(*plane, i)) ++hits;
  } else if (const auto* bowl = std::get_if<Bowl>(&terrain.shape)) {
    for (Eigen::Index i = 0; i < n; ++i)
      if (on_bowl(*bowl, i)) ++hits;
  } else {
    const auto& sphere = std::get<Sphere>(terrain.shape);
    Plane tangent;
    for (Eigen::Index i = 0; i < n; ++i)
      if (tangent_plane(sphere, x.col(i), tangent) && on_plane(tangent, i)) ++hits;
  }
  return hits;
}

// Lower and upper corners of the particles' bounding box: four particles (12 doubles) at a time
// into 12 running minima and maxima held in vector registers (Eigen's rowwise min and max would
// make six strided passes).
void bounding_box(const Vec3Array& x, Vec3& lo, Vec3& hi) {
  const Eigen::Index n = x.cols();
  if (n == 0) {
    lo = hi = Vec3::Zero();
    return;
  }
  const double* p = x.data();
  using Block = Eigen::Array<double, 12, 1>;  // four particles: x y z x y z x y z x y z
  Block l, h;
  for (int k = 0; k < 12; ++k) l[k] = h[k] = p[k % 3];
  const Eigen::Index blocks = n / 4;
  for (Eigen::Index j = 0; j < blocks; ++j) {
    const Eigen::Map<const Block> q(p + 12 * j);
    l = l.min(q);
    h = h.max(q);
  }
  for (Eigen::Index i = 4 * blocks; i < n; ++i)
    for (int d = 0; d < 3; ++d) {
      l[d] = std::min(l[d], p[3 * i + d]);
      h[d] = std::max(h[d], p[3 * i + d]);
    }
  for (int d = 0; d < 3; ++d) {  // slot k holds coordinate k % 3
    for (int k = d + 3; k < 12; k += 3) {
      l[d] = std::min(l[d], l[k]);
      h[d] = std::max(h[d], h[k]);
    }
  }
  lo = Vec3(l[0], l[1], l[2]);
  hi = Vec3(h[0], h[1], h[2]);
}

}  // namespace

void TerrainPhysics::acceleration(const State& s, Vec3Array& a) {
  World& w = world();
  EffectCounters& effects = counters(w);
  Vec3Array& force = force_scratch(w);
  const std::optional<Vec3>& gravity = w.gravity();
  ++effects.acceleration_evaluations;
  const Eigen::Index n = s.size();
  force.resize(3, n);
  // 1. Gravity (only when the scene has it).
  double* f = force.data();
  const double* m = w.masses().data();
  if (gravity) {
    ++effects.gravity_applications;
    const double g0 = gravity->x(), g1 = gravity->y(), g2 = gravity->z();
    for (Eigen::Index i = 0; i < n; ++i) {  // column i: m_i g
      f[3 * i] = g0 * m[i];
      f[3 * i + 1] = g1 * m[i];
      f[3 * i + 2] = g2 * m[i];
    }
  } else {
    force.setZero();
  }
  // 2. Springs and dampers of every group the scene built: in one call when the task library
  //    offers a spring engine, else group by group.
  add_spring_forces(w, s, force);
  // 3. Contact forces, terrain by terrain in scene order (contract §5).
  contact_pass(s, force);
  // 4. Divide by the mass.
  a.resize(3, n);
  double* out = a.data();
  for (Eigen::Index i = 0; i < n; ++i) {
    out[3 * i] = f[3 * i] / m[i];
    out[3 * i + 1] = f[3 * i + 1] / m[i];
    out[3 * i + 2] = f[3 * i + 2] / m[i];
  }
}

void TerrainPhysics::contact_pass(const State& s, Vec3Array& f) {
  World& w = world();
  const std::vector<Terrain>& terrains = w.terrains();
  EffectCounters& effects = counters(w);
  if (terrains.empty()) return;
  bool box_ready = false;
  Vec3 lo, hi;
  const Eigen::Index n = s.size();
  for (std::size_t t = 0; t < terrains.size(); ++t) {
    const Terrain& terrain = terrains[t];
    if (!terrain.contact) continue;
    if (!box_ready) {
      bounding_box(s.x, lo, hi);
      box_ready = true;
    }
    // Exact broad phase: contact needs φ < ε somewhere in the box.
    if (!(min_signed_distance(terrain, lo, hi) < terrain.surface().epsilon) ||
        box_outside_extent(terrain, lo, hi)) {
      ++effects.broadphase_skips[t];
      continue;
    }
    effects.contact_queries[t] += static_cast<std::int64_t>(n);
    // A particle's force changes only where the student's function says it made contact.
    const auto contact = [&](auto task) {
      return [&, task](const auto& surface, Eigen::Index i) {
        Vec3 fi = f.col(i);
        if (!task(surface, s.x.col(i), s.v.col(i), fi)) return false;
        f.col(i) = fi;
        return true;
      };
    };
    effects.contacts[t] += count_per_particle(terrain, s.x, contact(w.tasks().contact_plane),
                                              contact(w.tasks().contact_bowl));
  }
}

void TerrainPhysics::apply_collisions(State& s) {
  World& w = world();
  const std::vector<Terrain>& terrains = w.terrains();
  EffectCounters& effects = counters(w);
  if (terrains.empty()) return;
  ++effects.collision_passes;
  const Eigen::Index n = s.size();
  for (std::size_t t = 0; t < terrains.size(); ++t) {
    const Terrain& terrain = terrains[t];
    if (!terrain.collision && !terrain.project) continue;
    // The box is recomputed per terrain: an earlier terrain's projection may have moved particles.
    Vec3 lo, hi;
    bounding_box(s.x, lo, hi);
    const bool may_touch = min_signed_distance(terrain, lo, hi) < terrain.surface().epsilon &&
                           !box_outside_extent(terrain, lo, hi);
    if (!may_touch) {
      ++effects.broadphase_skips[t];
      continue;
    }
    if (terrain.collision) {
      effects.collision_queries[t] += static_cast<std::int64_t>(n);
      // A particle's velocity changes only where the student's function says it collided.
      const auto collide = [&](auto task) {
        return [&, task](const auto& surface, Eigen::Index i) {
          Vec3 vi = s.v.col(i);
          if (!task(surface, s.x.col(i), vi)) return false;
          s.v.col(i) = vi;
          return true;
        };
      };
      effects.collisions[t] += count_per_particle(terrain, s.x, collide(w.tasks().collide_plane),
                                                  collide(w.tasks().collide_bowl));
    }
    if (terrain.project) {
      // Optional effect (contract §5): particles behind the surface, inside the extent, are moved
      // onto it along the normal.
      for (Eigen::Index i = 0; i < n; ++i) {
        const Vec3 x = s.x.col(i);
        if (!in_extent(terrain, x)) continue;
        const double phi = signed_distance(terrain, x);
        if (phi < 0.0) s.x.col(i) = x - phi * surface_normal(terrain, x);
      }
    }
  }
}

}  // namespace jelly
