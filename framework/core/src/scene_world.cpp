// From a validated SceneSpec to a World, and the course's terrain presets.
#include <algorithm>
#include <cmath>

#include "jelly/body_kind.hpp"
#include "jelly/scene.hpp"

namespace jelly {

std::string SceneError::text() const {
  std::string out = file.empty() ? std::string("<scene>") : file;
  if (line > 0) {
    out += ':' + std::to_string(line);
    if (column > 0) out += ':' + std::to_string(column);
  }
  out += ": ";
  if (!key.empty()) out += key + ": ";
  out += message;
  return out;
}

namespace {

Terrain plane_terrain(std::string name, Vec3 point, Vec3 normal, double friction) {
  Plane p;
  p.point = point;
  p.normal = normal.normalized();
  p.surface.friction = friction;
  return Terrain{std::move(name), p};
}

}  // namespace

std::optional<Terrain> terrain_preset(std::string_view name) {
  const double r = 9.0 / std::sqrt(2.0);  // 2023: hole radius = bowl rim radius = 9/√2
  if (name == "course-2023-floor") {
    Terrain t = plane_terrain("floor", {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0.2);
    auto& p = std::get<Plane>(t.shape);
    p.has_hole = true;
    p.hole_center = Vec3(2.0, 0.0, 1.0);
    p.hole_radius = r;
    return t;
  }
  if (name == "course-2023-bowl") {
    Bowl b;
    b.center = Vec3(2.0, r, 1.0);
    b.radius = 9.0;
    b.rim_height = 0.0;
    b.surface.friction = 0.2;
    return Terrain{"bowl", b};
  }
  if (name == "course-2021-plane")
    return plane_terrain("plane", {0.0, -1.0, 0.0}, {0.0, 1.0, 0.0}, 0.3);
  if (name == "course-2021-tilted")
    return plane_terrain("tilted", {0.0, -1.0, 0.0}, {1.0, 1.0, 0.0}, 0.3);
  if (name == "course-2021-sphere") {
    Sphere s;
    s.center = Vec3(0.0, -1.0, 0.0);
    s.radius = 3.0;
    s.surface.friction = 0.3;
    return Terrain{"sphere", s};
  }
  if (name == "course-2021-bowl") {
    Bowl b;
    b.center = Vec3(2.0, 7.0, 1.0);
    b.radius = 7.0;
    b.rim_height = 7.0;  // a hemisphere: the rim at the centre's height
    b.surface.friction = 0.3;
    return Terrain{"bowl", b};
  }
  return std::nullopt;
}

std::vector<std::string_view> terrain_preset_names() {
  return {"course-2023-floor",  "course-2023-bowl", "course-2021-plane",
          "course-2021-sphere", "course-2021-bowl", "course-2021-tilted"};
}

std::unique_ptr<World> build_world(const SceneSpec& scene, const TaskTable& tasks) {
  auto world = std::make_unique<World>(tasks);
  body_kind_of(scene).build(scene, *world);  // its body, springs, gravity, terrains or spheres
  return world;
}

}  // namespace jelly
