// Test helper: field-by-field comparison of two SceneSpecs, naming the first difference.
// Compares what a scene means: the body of its kind (the other kind's defaults are not part of
// it), spring coefficients only for present types, and not `source` (where it was read from).
#pragma once

#include <string>

#include "jelly/cloth_scene.hpp"
#include "jelly/cube_scene.hpp"
#include "jelly/particles_scene.hpp"
#include "jelly/scene.hpp"
#include "jelly/skeleton_scene.hpp"

namespace jelly::testing {

/// Empty when equal; otherwise the first field that differs, e.g. "terrains[1].radius: 9 vs 8".
inline std::string scene_difference(const SceneSpec& a, const SceneSpec& b) {
  const auto num = [](double x) { return std::to_string(x); };
  const auto v3 = [&](const Vec3& v) { return num(v.x()) + "," + num(v.y()) + "," + num(v.z()); };
#define JELLY_CMP(expr_a, expr_b, label, fmt) \
  if (!((expr_a) == (expr_b)))                \
    return std::string(label) + ": " + fmt(expr_a) + " vs " + fmt(expr_b);
  const auto str = [](const std::string& s) { return s; };
  const auto i = [](long long x) { return std::to_string(x); };
  JELLY_CMP(a.name, b.name, "name", str);
  JELLY_CMP(a.description, b.description, "description", str);
  JELLY_CMP(static_cast<int>(a.integrator), static_cast<int>(b.integrator), "integrator", i);
  JELLY_CMP(a.dt, b.dt, "dt", num);
  JELLY_CMP(a.duration, b.duration, "duration", num);
  JELLY_CMP(a.auto_dt, b.auto_dt, "auto_dt", i);
  JELLY_CMP(a.gravity.has_value(), b.gravity.has_value(), "gravity present", i);
  if (a.gravity) JELLY_CMP(*a.gravity, *b.gravity, "gravity", v3);
  JELLY_CMP(std::string(a.body_kind.name), std::string(b.body_kind.name), "body kind", str);
  if (a.body_kind == kCubeKind) {
    JELLY_CMP(cube_spec(a).n, cube_spec(b).n, "cube.n", i);
    JELLY_CMP(cube_spec(a).edge, cube_spec(b).edge, "cube.edge", num);
    JELLY_CMP(cube_spec(a).mass, cube_spec(b).mass, "cube.mass", num);
    JELLY_CMP(cube_spec(a).center, cube_spec(b).center, "cube.center", v3);
    JELLY_CMP(cube_spec(a).velocity, cube_spec(b).velocity, "cube.velocity", v3);
    JELLY_CMP(cube_spec(a).rotation_axis, cube_spec(b).rotation_axis, "cube.rotation_axis", v3);
    JELLY_CMP(cube_spec(a).rotation_degrees, cube_spec(b).rotation_degrees, "cube.rotation_degrees",
              num);
  } else if (a.body_kind == kSkeletonKind) {
    const SkeletonSceneSpec& c = skeleton_scene(a);
    const SkeletonSceneSpec& d = skeleton_scene(b);
    JELLY_CMP(c.asf, d.asf, "skeleton.asf", str);
    JELLY_CMP(c.amc, d.amc, "skeleton.amc", str);
    JELLY_CMP(c.scale, d.scale, "skeleton.scale", num);
    JELLY_CMP(c.fps, d.fps, "skeleton.fps", num);
    JELLY_CMP(static_cast<int>(c.mode), static_cast<int>(d.mode), "skeleton.mode", i);
    JELLY_CMP(c.frames, d.frames, "skeleton.frames", i);
    JELLY_CMP(c.keyframe_in, d.keyframe_in, "skeleton.keyframe_in", i);
    JELLY_CMP(c.keyframe_out, d.keyframe_out, "skeleton.keyframe_out", i);
    JELLY_CMP(c.amc_b, d.amc_b, "skeleton.amc_b", str);
    JELLY_CMP(c.a, d.a, "skeleton.a", i);
    JELLY_CMP(c.b, d.b, "skeleton.b", i);
    JELLY_CMP(c.window, d.window, "skeleton.window", i);
  } else if (a.body_kind == kClothKind) {
    const ClothSpec& c = cloth_spec(a);
    const ClothSpec& d = cloth_spec(b);
    JELLY_CMP(c.n, d.n, "cloth.n", i);
    JELLY_CMP(c.size, d.size, "cloth.size", num);
    JELLY_CMP(c.mass, d.mass, "cloth.mass", num);
    JELLY_CMP(c.center, d.center, "cloth.center", v3);
    JELLY_CMP(c.velocity, d.velocity, "cloth.velocity", v3);
    JELLY_CMP(c.rotation_axis, d.rotation_axis, "cloth.rotation_axis", v3);
    JELLY_CMP(c.rotation_degrees, d.rotation_degrees, "cloth.rotation_degrees", num);
    JELLY_CMP(c.air_drag, d.air_drag, "cloth.air_drag", num);
    if (c.pin_sets != d.pin_sets) return "cloth.pin_sets differ";
    if (c.pins != d.pins) return "cloth.pins differ";
    const ClothCollisionSettings& e = cloth_collisions(a);
    const ClothCollisionSettings& f = cloth_collisions(b);
    JELLY_CMP(e.cloth_restitution, f.cloth_restitution, "collision.cloth_restitution", num);
    JELLY_CMP(e.sphere_restitution, f.sphere_restitution, "collision.sphere_restitution", num);
    JELLY_CMP(e.tolerance, f.tolerance, "collision.tolerance", num);
    JELLY_CMP(e.friction, f.friction, "collision.friction", num);
    JELLY_CMP(e.push_out, f.push_out, "collision.push_out", num);
    JELLY_CMP(sphere_specs(a).size(), sphere_specs(b).size(), "sphere count", i);
    for (std::size_t k = 0; k < sphere_specs(a).size(); ++k) {
      const SphereSpec& p = sphere_specs(a)[k];
      const SphereSpec& q = sphere_specs(b)[k];
      const std::string at = "spheres[" + std::to_string(k) + "]";
      JELLY_CMP(p.center, q.center, at + ".center", v3);
      JELLY_CMP(p.radius, q.radius, at + ".radius", num);
      JELLY_CMP(p.kinematic, q.kinematic, at + ".kinematic", i);
      // The mass the sphere has (a mass given equal to 1000·r³ means the same sphere).
      JELLY_CMP(p.mass.value_or(default_sphere_mass(p.radius)),
                q.mass.value_or(default_sphere_mass(q.radius)), at + ".mass", num);
      if (!p.kinematic) JELLY_CMP(p.velocity, q.velocity, at + ".velocity", v3);
      JELLY_CMP(p.schedule.size(), q.schedule.size(), at + ".schedule size", i);
      for (std::size_t m = 0; m < p.schedule.size(); ++m) {
        JELLY_CMP(p.schedule[m].time, q.schedule[m].time, at + ".schedule.time", num);
        JELLY_CMP(p.schedule[m].velocity, q.schedule[m].velocity, at + ".schedule.velocity", v3);
      }
    }
  } else {
    const ParticleBodySpec& p = particles_scene(a);
    const ParticleBodySpec& q = particles_scene(b);
    JELLY_CMP(p.mass, q.mass, "particles.mass", num);
    JELLY_CMP(p.positions.cols(), q.positions.cols(), "particles.positions count", i);
    if (p.positions != q.positions) return "particles.positions differ";
    JELLY_CMP(p.velocities.cols(), q.velocities.cols(), "particles.velocities count", i);
    if (p.velocities != q.velocities) return "particles.velocities differ";
    JELLY_CMP(static_cast<int>(p.spring_type), static_cast<int>(q.spring_type),
              "particles.spring_type", i);
    JELLY_CMP(p.springs.size(), q.springs.size(), "particles.springs count", i);
    for (std::size_t k = 0; k < p.springs.size(); ++k) {
      const std::string at = "particles.springs[" + std::to_string(k) + "]";
      JELLY_CMP(p.springs[k].a, q.springs[k].a, at + ".a", i);
      JELLY_CMP(p.springs[k].b, q.springs[k].b, at + ".b", i);
      JELLY_CMP(p.springs[k].rest_length, q.springs[k].rest_length, at + ".rest_length", num);
    }
  }
  const std::pair<const SpringSettings*, const SpringSettings*> springs[] = {
      {&a.structural, &b.structural},
      {&a.shear, &b.shear},
      {&a.shear_body, &b.shear_body},
      {&a.bending, &b.bending}};
  const char* names[] = {"structural", "shear", "shear_body", "bending"};
  for (int k = 0; k < 4; ++k) {
    const std::string at = std::string("springs.") + names[k];
    JELLY_CMP(springs[k].first->enabled, springs[k].second->enabled, at + ".enabled", i);
    if (!springs[k].first->enabled) continue;
    JELLY_CMP(springs[k].first->ks, springs[k].second->ks, at + ".ks", num);
    JELLY_CMP(springs[k].first->kd, springs[k].second->kd, at + ".kd", num);
  }
  JELLY_CMP(a.terrains.size(), b.terrains.size(), "terrain count", i);
  for (std::size_t k = 0; k < a.terrains.size(); ++k) {
    const Terrain& s = a.terrains[k];
    const Terrain& t = b.terrains[k];
    const std::string at = "terrains[" + std::to_string(k) + "]";
    JELLY_CMP(s.name, t.name, at + ".name", str);
    JELLY_CMP(s.shape.index(), t.shape.index(), at + ".type", i);
    JELLY_CMP(s.collision, t.collision, at + ".collision", i);
    JELLY_CMP(s.contact, t.contact, at + ".contact", i);
    JELLY_CMP(s.project, t.project, at + ".project", i);
    JELLY_CMP(s.surface().epsilon, t.surface().epsilon, at + ".epsilon", num);
    JELLY_CMP(s.surface().restitution, t.surface().restitution, at + ".restitution", num);
    JELLY_CMP(s.surface().friction, t.surface().friction, at + ".friction", num);
    if (const auto* p = std::get_if<Plane>(&s.shape)) {
      const Plane& q = std::get<Plane>(t.shape);
      JELLY_CMP(p->point, q.point, at + ".point", v3);
      JELLY_CMP(p->normal, q.normal, at + ".normal", v3);
      JELLY_CMP(p->has_hole, q.has_hole, at + ".has_hole", i);
      if (p->has_hole) {
        JELLY_CMP(p->hole_center, q.hole_center, at + ".hole_center", v3);
        JELLY_CMP(p->hole_radius, q.hole_radius, at + ".hole_radius", num);
      }
    } else if (const auto* bw = std::get_if<Bowl>(&s.shape)) {
      const Bowl& q = std::get<Bowl>(t.shape);
      JELLY_CMP(bw->center, q.center, at + ".center", v3);
      JELLY_CMP(bw->radius, q.radius, at + ".radius", num);
      JELLY_CMP(bw->rim_height, q.rim_height, at + ".rim_height", num);
    } else {
      const Sphere& p2 = std::get<Sphere>(s.shape);
      const Sphere& q = std::get<Sphere>(t.shape);
      JELLY_CMP(p2.center, q.center, at + ".center", v3);
      JELLY_CMP(p2.radius, q.radius, at + ".radius", num);
    }
  }
#undef JELLY_CMP
  return {};
}

}  // namespace jelly::testing
