// libFuzzer target for the scene loader: parse_scene must never crash, hang or trip a sanitizer,
// whatever the text; and whatever it accepts must survive writing and reading back
// (to_toml is a fixed point) and get/set of every parameter.
//
// Lines "#set key=value" in the input (TOML comments, so the loader ignores them) are applied
// with set_parameter after loading, to fuzz the --set path too.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "jelly/cloth_scene.hpp"
#include "jelly/cube_scene.hpp"
#include "jelly/params.hpp"
#include "jelly/particles_scene.hpp"
#include "jelly/scene.hpp"
#include "jelly/skeleton_scene.hpp"

namespace {

[[noreturn]] void fail(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz_scene: %s\n%s\n", what, detail.c_str());
  std::abort();
}

/// A skeleton scene: its files named, its numbers in range (those bounded by the motion are
/// checked when it is read), a keyframe whole, a blend's motion B named, nothing simulated.
void check_valid_skeleton(const jelly::SceneSpec& s) {
  const jelly::SkeletonSceneSpec& k = jelly::skeleton_scene(s);
  if (k.asf.empty() || k.amc.empty()) fail("accepted a skeleton scene without its files", "");
  if (!(k.scale > 0.0) || !(k.fps > 0.0)) fail("accepted a bad skeleton scale or fps", "");
  if (k.frames < 0 || k.frames == 1) fail("accepted a warp of fewer than 2 frames", "");
  for (long long key : {k.keyframe_in, k.keyframe_out})
    if (key < -1 || key == 0) fail("accepted a keyframe at 0 or below -1", std::to_string(key));
  if ((k.keyframe_in < 0) != (k.keyframe_out < 0)) fail("accepted half a keyframe", "");
  if (k.a < 0 || k.b < 0 || k.window < 2) fail("accepted a bad blend", "");
  if (k.mode == jelly::SkeletonMode::Blend && k.amc_b.empty())
    fail("accepted a blend without motion B", "");
  if (!s.terrains.empty() || s.gravity) fail("accepted a terrain or gravity in a skeleton", "");
}

/// What validation promises about an accepted scene (what build_world and the simulation rely on).
void check_valid(const jelly::SceneSpec& s) {
  if (!(s.dt > 0.0) || !(s.duration > 0.0)) fail("accepted a non-positive dt or duration", "");
  if (s.body_kind == jelly::kCubeKind) {
    if (cube_spec(s).n < 2 || cube_spec(s).n > 64 || !(cube_spec(s).mass > 0.0) ||
        !(cube_spec(s).edge > 0.0))
      fail("accepted a bad cube", std::to_string(cube_spec(s).n));
  } else if (s.body_kind == jelly::kClothKind) {
    const jelly::ClothSpec& c = cloth_spec(s);
    if (c.n < 2 || c.n > 200 || !(c.mass > 0.0) || !(c.size > 0.0) || !(c.air_drag >= 0.0))
      fail("accepted a bad cloth", std::to_string(c.n));
    for (const std::string& set : c.pin_sets)
      if (set != "corners" && set != "edge") fail("accepted an unknown pin set", set);
    for (const jelly::GridCoord& p : c.pins)
      if (p[0] < 0 || p[1] < 0 || p[0] >= c.n || p[1] >= c.n)
        fail("accepted a pin outside the grid", std::to_string(p[0]) + "," + std::to_string(p[1]));
    if (!s.terrains.empty()) fail("accepted a terrain in a cloth scene", "");
    if (s.shear_body.enabled) fail("accepted body diagonals in a cloth", "");
    const jelly::ClothCollisionSettings& k = cloth_collisions(s);
    if (!(k.cloth_restitution >= 0.0 && k.cloth_restitution <= 1.0) ||
        !(k.sphere_restitution >= 0.0 && k.sphere_restitution <= 1.0) || !(k.tolerance >= 0.0) ||
        !(k.friction >= 0.0) || !(k.push_out >= 0.0 && k.push_out <= 1.0))
      fail("accepted bad collision settings", "");
    for (const jelly::SphereSpec& sp : sphere_specs(s)) {
      if (!(sp.radius > 0.0) || (sp.mass && !(*sp.mass > 0.0)))
        fail("accepted a bad sphere", std::to_string(sp.radius));
      for (std::size_t i = 1; i < sp.schedule.size(); ++i)
        if (!(sp.schedule[i].time > sp.schedule[i - 1].time))
          fail("accepted a schedule whose times do not increase", "");
    }
  } else if (s.body_kind == jelly::kSkeletonKind) {
    check_valid_skeleton(s);
  } else {
    const auto n = particles_scene(s).positions.cols();
    if (n < 1 || particles_scene(s).velocities.cols() != n || !(particles_scene(s).mass > 0.0))
      fail("accepted bad particles", "");
    for (const jelly::Spring& sp : particles_scene(s).springs)
      if (sp.a < 0 || sp.b < 0 || sp.a >= n || sp.b >= n || sp.a == sp.b || !(sp.rest_length > 0.0))
        fail("accepted a bad spring", std::to_string(sp.a) + "," + std::to_string(sp.b));
  }
  if (s.body_kind != jelly::kClothKind && !sphere_specs(s).empty())
    fail("accepted spheres in a scene without a cloth", "");
  for (const jelly::Terrain& t : s.terrains) {
    if (const auto* p = std::get_if<jelly::Plane>(&t.shape)) {
      if (std::abs(p->normal.norm() - 1.0) > 1e-12) fail("plane normal not unit", t.name);
      if (p->has_hole && !(p->hole_radius > 0.0)) fail("hole radius not positive", t.name);
    } else if (const auto* b = std::get_if<jelly::Bowl>(&t.shape)) {
      if (!(b->rim_height > b->center.y() - b->radius && b->rim_height <= b->center.y()))
        fail("bowl rim outside the sphere", t.name);
    }
    const jelly::SurfaceProperties& sp = t.surface();
    if (!(sp.epsilon > 0.0) || !(sp.restitution >= 0.0 && sp.restitution <= 1.0) ||
        !(sp.friction >= 0.0))
      fail("bad surface", t.name);
  }
}

void check_round_trip(const jelly::SceneSpec& s, const char* stage) {
  const std::string text = jelly::to_toml(s);
  const jelly::SceneResult again = jelly::parse_scene(text, "round-trip");
  if (!again) fail(stage, "to_toml output does not load: " + again.error->text() + "\n" + text);
  if (jelly::to_toml(*again.scene) != text) fail(stage, "to_toml is not a fixed point:\n" + text);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const jelly::SceneResult r = jelly::parse_scene(text, "fuzz-input");
  if (!r) {
    if (!r.error || r.error->message.empty()) fail("no error message", std::string(text));
    (void)r.error->text();
    return 0;
  }
  jelly::SceneSpec s = *r.scene;
  check_valid(s);
  check_round_trip(s, "after loading");

  // Every parameter's text goes back through set_parameter unchanged.
  const std::string before = jelly::to_toml(s);
  for (const jelly::ParamInfo& p : jelly::scene_parameters(s)) {
    const auto value = jelly::get_parameter(s, p.key);
    if (!value) fail("listed parameter has no value", p.key);
    if (const auto e = jelly::set_parameter(s, p.key, *value)) fail("get/set rejected", e->text());
  }
  if (jelly::to_toml(s) != before) fail("get/set changed the scene", before);

  // "#set key=value" lines.
  std::size_t at = 0;
  bool changed = false;
  while ((at = text.find("#set ", at)) != std::string_view::npos) {
    at += 5;
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::string_view line = text.substr(at, end - at);
    const std::size_t eq = line.find('=');
    if (eq == std::string_view::npos) continue;
    if (!jelly::set_parameter(s, line.substr(0, eq), line.substr(eq + 1))) changed = true;
  }
  if (changed) {
    check_valid(s);
    check_round_trip(s, "after #set");
  }
  return 0;
}
