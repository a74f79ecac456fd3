// A cloth scene drawn: the cloth's two sides, the spheres in their colours, the pinned particles.
#include <algorithm>

#include "jelly/bodies/cloth/view/cloth_view.hpp"
#include "jelly/cloth_physics.hpp"

namespace jelly::cloth_view {

ClothDrawable::ClothDrawable(const World& world) {
  for (const ClothGrid& c : cloth_physics(world).cloths()) surfaces_.emplace_back(c);
  spheres_.resize(static_cast<std::size_t>(cloth_physics(world).sphere_count()));
}

void ClothDrawable::update(const World& world, const render::DrawOptions& options) {
  if (options.surface)
    for (ClothSurface& c : surfaces_) c.update(world.state().x);
  for (std::size_t i = 0; i < spheres_.size(); ++i) {
    const SphereBody sb = cloth_physics(world).sphere(static_cast<int>(i));
    spheres_[i].update(sb.center, sb.radius);
  }
}

void ClothDrawable::create_gpu(const render::Gl& gl, GLuint particle_positions) {
  for (const ClothSurface& c : surfaces_) {
    render::GpuMesh gm;
    gm.create(gl, true, true);
    gm.upload_indices(gl, c.mesh().indices);
    surface_gpu_.push_back(gm);
  }
  for (const MovingSphere& sphere : spheres_) {
    render::GpuMesh gm;
    gm.create(gl, true, true);
    gm.upload_indices(gl, sphere.mesh().indices);
    sphere_gpu_.push_back(gm);
  }
  // Pin markers read the particle positions buffer, as the springs do.
  if (!surfaces_.empty()) pins_gpu_.create_on(gl, particle_positions);
}

void ClothDrawable::destroy_gpu(const render::Gl& gl) {
  for (auto& m : surface_gpu_) m.destroy(gl);
  for (auto& m : sphere_gpu_) m.destroy(gl);
  pins_gpu_.destroy(gl);
  surface_gpu_.clear();
  sphere_gpu_.clear();
}

void ClothDrawable::draw_surfaces(const render::SurfacePass& pass, const World& world,
                                  const render::DrawOptions& options) {
  if (options.surface && !surfaces_.empty()) {
    pass.set_int("u_plane", 0);
    pass.set_int("u_has_hole", 0);
    pass.set_int("u_two_tone", 1);
    pass.set_color("u_color", kClothFront);
    pass.set_color("u_back_color", kClothBack);
    pass.set_material(kClothMaterial);
    for (std::size_t i = 0; i < surfaces_.size(); ++i)
      pass.draw_streamed(surfaces_[i].mesh(), surface_gpu_[i], true);
    pass.set_int("u_two_tone", 0);
  }
  if (spheres_.empty()) return;
  pass.set_int("u_plane", 0);
  pass.set_int("u_has_hole", 0);
  pass.set_material(kSphereMaterial);
  for (std::size_t i = 0; i < spheres_.size(); ++i) {
    pass.set_color("u_color", cloth_physics(world).sphere_is_kinematic(static_cast<int>(i))
                                  ? kKinematicSphere
                                  : kDynamicSphere);
    pass.draw_streamed(spheres_[i].mesh(), sphere_gpu_[i], false);
  }
}

bool ClothDrawable::has_markers(const render::DrawOptions& options) const {
  return options.markers && !surfaces_.empty();
}

void ClothDrawable::draw_markers(const render::PointPass& pass, const World& world,
                                 const render::DrawOptions& /*options*/) {
  pin_indices_.clear();
  for (const ClothGrid& c : cloth_physics(world).cloths())
    for (int p = c.first_index(); p < c.first_index() + c.particle_count(); ++p)
      if (cloth_physics(world).is_pinned(p)) pin_indices_.push_back(static_cast<std::uint32_t>(p));
  if (pin_indices_.empty()) return;
  pass.draw_points(pins_gpu_, pin_indices_, std::max(kMinPinSize, kPinSizeFactor * pass.dot_size()),
                   kPin);
}

long ClothDrawable::dot_count(const World& world) const {
  // A cloth scene's dynamic spheres are particles of the state too: only the cloth's are dots.
  if (surfaces_.empty()) return -1;
  return static_cast<long>(cloth_physics(world).cloth_particle_count());
}

}  // namespace jelly::cloth_view
