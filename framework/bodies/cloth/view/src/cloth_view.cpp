// The cloth kind's view: framing, caption lines, replay points and the viewer's names and help
// for a cloth scene (its drawable: cloth_drawable.cpp; its keys and panel: cloth_viewer.cpp, in
// jelly_cloth_view_controls).
#include <string>

#include "jelly/bodies/cloth/view/cloth_view.hpp"
#include "jelly/cloth_physics.hpp"
#include "jelly/cloth_scene.hpp"
#include "jelly/session/captions.hpp"

namespace jelly::cloth_view {

namespace {

using session::format_number;

/// Indices of the world's kinematic spheres, in scene order.
std::vector<int> kinematic_spheres(const World& world) {
  std::vector<int> out;
  const ClothPhysics& cloth = cloth_physics(world);
  for (int i = 0; i < cloth.sphere_count(); ++i)
    if (cloth.sphere_is_kinematic(i)) out.push_back(i);
  return out;
}

class ClothView final : public render::BodyView {
 public:
  std::string_view kind() const override { return "cloth"; }
  bool present(const World& world) const override {
    const ClothPhysics& cloth = cloth_physics(world);  // none: an empty one
    return !cloth.cloths().empty() || cloth.sphere_count() > 0;
  }
  std::unique_ptr<render::BodyDrawable> make_drawable(const World& world) const override {
    return std::make_unique<ClothDrawable>(world);
  }
  bool frame(const World& world, const std::function<void(const Vec3&)>& grow) const override;
  std::string caption_body(const SceneSpec& sc) const override;
  std::string caption_tail(const SceneSpec& sc) const override;

  long replay_points(const World& world) const override {
    return static_cast<long>(kinematic_spheres(world).size());
  }
  std::string replay_points_name() const override { return "kinematic sphere centres"; }
  void place_replay_points(World& world, const Vec3Array& x, long first) const override {
    const std::vector<int> kinematic = kinematic_spheres(world);
    for (std::size_t j = 0; j < kinematic.size(); ++j)
      cloth_physics(world).place_sphere(kinematic[j], x.col(first + static_cast<long>(j)));
  }
  std::string_view replay_help() const override {
    return "; a cloth\n"
           "             scene's frames may end with its kinematic spheres' centres (as the "
           "grader\n"
           "             records them)";
  }

  std::string_view surface_label() const override { return "cloth surface"; }
  std::string_view markers_label() const override { return "pinned particles"; }
  bool shows_spring_type(SpringType type) const override {
    return type != SpringType::ShearBody;  // a 3D lattice's
  }
  std::string_view panel_title() const override { return "Cloth"; }
  std::string_view panel_id() const override { return "cloth"; }
  std::string_view keys_help() const override {
    return "cloth scenes: 1-4 pin/unpin a corner, arrows drive the kinematic sphere (2 m/s), S "
           "stops it";
  }
};

/// A cloth where it was built, with room below it for its sag (half its side) and around it for
/// its swing (a tenth of its side); every sphere where it is now. The particles are framed where
/// they are now too (false: the cloth does not cover them).
bool ClothView::frame(const World& world, const std::function<void(const Vec3&)>& grow) const {
  for (const ClothGrid& c : cloth_physics(world).cloths()) {
    const double side = c.spacing() * (c.n() - 1);
    const Vec3 swing = Vec3::Constant(0.1 * side);
    for (Eigen::Index i = 0; i < c.initial_positions().cols(); ++i) {
      const Vec3 p = c.initial_positions().col(i);
      grow(p + swing);
      grow(p - swing - Vec3(0.0, 0.5 * side, 0.0));
    }
  }
  for (int i = 0; i < cloth_physics(world).sphere_count(); ++i) {
    const SphereBody sb = cloth_physics(world).sphere(i);
    grow(sb.center - Vec3::Constant(sb.radius));
    grow(sb.center + Vec3::Constant(sb.radius));
  }
  return false;
}

std::string ClothView::caption_body(const SceneSpec& sc) const {
  const ClothSpec& c = cloth_spec(sc);
  std::string pins;
  for (const std::string& p : c.pin_sets) pins += (pins.empty() ? "" : "+") + p;
  if (!c.pins.empty()) pins += (pins.empty() ? "" : "+") + std::to_string(c.pins.size());
  return "\ncloth: n = " + std::to_string(c.n) + ", L = " + format_number("%.3g m", c.size) +
         ", m = " + format_number("%.3g kg", c.mass) + ", pins " + (pins.empty() ? "none" : pins) +
         (c.air_drag > 0.0 ? ", k_air " + format_number("%g", c.air_drag) : std::string()) + "\n";
}

std::string ClothView::caption_tail(const SceneSpec& sc) const {
  const ClothCollisionSettings& k = cloth_collisions(sc);
  std::size_t kinematic = 0;
  for (const SphereSpec& sp : sphere_specs(sc)) kinematic += sp.kinematic ? 1 : 0;
  const std::size_t n = sphere_specs(sc).size();
  return "\n" + std::to_string(n) + (n == 1 ? " sphere (" : " spheres (") +
         std::to_string(kinematic) + " kinematic): e_cloth " +
         format_number("%g", k.cloth_restitution) + " e_sphere " +
         format_number("%g", k.sphere_restitution) + " eps " + format_number("%g", k.tolerance) +
         " mu " + format_number("%g", k.friction) + " beta " + format_number("%g", k.push_out) +
         "   ";
}

}  // namespace

const render::BodyView& body_view() {
  static const ClothView view;
  return view;
}

}  // namespace jelly::cloth_view
