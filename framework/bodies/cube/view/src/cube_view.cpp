// The cube kind's view: its drawable (the jelly surfaces) and what the frame and the viewer say of
// a cube scene.
#include <cstdio>
#include <string>

#include "jelly/bodies/cube/view/cube_view.hpp"
#include "jelly/cube_physics.hpp"
#include "jelly/cube_scene.hpp"
#include "jelly/session/captions.hpp"

namespace jelly::cube_view {

CubeDrawable::CubeDrawable(const World& world) {
  for (const CubeLattice& c : cubes_of(world)) surfaces_.emplace_back(c);
}

void CubeDrawable::update(const World& world, const render::DrawOptions& options) {
  if (!options.surface) return;
  for (JellySurface& s : surfaces_) s.update(world.state().x);
}

void CubeDrawable::create_gpu(const render::Gl& gl, GLuint /*particle_positions*/) {
  for (const JellySurface& s : surfaces_) {
    render::GpuMesh gm;
    gm.create(gl, true, true);
    gm.upload_indices(gl, s.mesh().indices);
    gpu_.push_back(gm);
  }
}

void CubeDrawable::destroy_gpu(const render::Gl& gl) {
  for (auto& m : gpu_) m.destroy(gl);
  gpu_.clear();
}

void CubeDrawable::draw_surfaces(const render::SurfacePass& pass, const World& /*world*/,
                                 const render::DrawOptions& options) {
  if (!options.surface) return;
  pass.set_int("u_plane", 0);
  pass.set_int("u_has_hole", 0);
  pass.set_color("u_color", kJellyColor);
  pass.set_material(kJellyMaterial);
  for (std::size_t i = 0; i < surfaces_.size(); ++i)
    pass.draw_streamed(surfaces_[i].mesh(), gpu_[i], true);
}

namespace {

class CubeView final : public render::BodyView {
 public:
  std::string_view kind() const override { return "cube"; }
  bool present(const World& world) const override { return !cubes_of(world).empty(); }
  std::unique_ptr<render::BodyDrawable> make_drawable(const World& world) const override {
    return std::make_unique<CubeDrawable>(world);
  }
  /// The cubes where they were built, so the framing does not depend on when it is computed.
  bool frame(const World& world, const std::function<void(const Vec3&)>& grow) const override {
    for (const CubeLattice& c : cubes_of(world))
      for (Eigen::Index i = 0; i < c.initial_positions().cols(); ++i)
        grow(c.initial_positions().col(i));
    return true;
  }
  std::string caption_body(const SceneSpec& sc) const override {
    using session::format_number;
    return "\ncube: n = " + std::to_string(cube_spec(sc).n) +
           ", L = " + format_number("%.3g m", cube_spec(sc).edge) +
           ", m = " + format_number("%.3g kg", cube_spec(sc).mass) + "\n";
  }
  std::string_view surface_label() const override { return "jelly surface"; }
};

}  // namespace

const render::BodyView& body_view() {
  static const CubeView view;
  return view;
}

}  // namespace jelly::cube_view
