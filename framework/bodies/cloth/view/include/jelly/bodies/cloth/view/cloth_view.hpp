// The cloth's view module (a body kind's GL side, jelly/render/body_view.hpp): the cloth's
// two-sided surface, its pins, the spheres of a cloth scene, their colours and materials; its
// caption lines, its replay points (the kinematic spheres' centres) and its viewer controls
// (cloth_controls.hpp).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "jelly/cloth.hpp"
#include "jelly/render/body_view.hpp"
#include "jelly/render/meshes.hpp"

namespace jelly::cloth_view {

/// Colours (linear RGB, 0–1; the tests classify pixels with them): the cloth's front (+y side when
/// flat) and back, its pins, and the spheres (dynamic ones are integrated, kinematic ones follow a
/// schedule or the arrow keys).
inline const Eigen::Vector3f kClothFront{0.80f, 0.62f, 0.20f};
inline const Eigen::Vector3f kClothBack{0.52f, 0.38f, 0.86f};
inline const Eigen::Vector3f kPin{0.95f, 0.12f, 0.10f};
inline const Eigen::Vector3f kDynamicSphere{0.80f, 0.33f, 0.60f};
inline const Eigen::Vector3f kKinematicSphere{0.30f, 0.72f, 0.50f};
inline constexpr render::Material kClothMaterial{0.12f, 20.0f};   ///< fabric, a soft sheen
inline constexpr render::Material kSphereMaterial{0.35f, 40.0f};  ///< the spheres
/// Pinned particles: this many times the particle dot size, never below the minimum [px].
inline constexpr float kPinSizeFactor = 2.2f;
inline constexpr float kMinPinSize = 6.0f;

/// The surface of one cloth (assignment A2): two triangles per grid cell, one vertex per particle
/// (vertex i·n + k follows particle first + i·n + k). Front faces wind counter-clockwise seen
/// from +y for a cloth built flat (rotation 0), so the renderer tints the side towards +y as the
/// front and the other as the back. update() copies the positions and recomputes area-weighted
/// vertex normals (those of the front side).
class ClothSurface {
 public:
  /// A cloth of n×n particles whose first particle is column `first_index` of the state.
  ClothSurface(int n, int first_index);
  explicit ClothSurface(const ClothGrid& grid) : ClothSurface(grid.n(), grid.first_index()) {}
  /// Positions from state x (3×N over the whole world).
  void update(const Vec3Array& x);
  const render::Mesh& mesh() const { return mesh_; }
  int n() const { return n_; }
  int first_index() const { return first_; }

 private:
  int n_;
  int first_;
  render::Mesh mesh_;
};

/// A sphere of a cloth scene drawn where it is now: a unit sphere's directions, moved and scaled
/// by update(). Coarser than render::sphere_mesh() (it is re-uploaded every frame).
class MovingSphere {
 public:
  MovingSphere();
  void update(const Vec3& center, double radius);
  const render::Mesh& mesh() const { return mesh_; }

 private:
  std::vector<Eigen::Vector3f> directions_;
  render::Mesh mesh_;
};

/// The draw proxies of a cloth scene: one surface per cloth, one moving sphere per World sphere
/// (World::sphere() order), the pin markers.
class ClothDrawable : public render::BodyDrawable {
 public:
  explicit ClothDrawable(const World& world);
  const std::vector<ClothSurface>& cloth_surfaces() const { return surfaces_; }
  const std::vector<MovingSphere>& spheres() const { return spheres_; }

  void update(const World& world, const render::DrawOptions& options) override;
  void create_gpu(const render::Gl& gl, GLuint particle_positions) override;
  void destroy_gpu(const render::Gl& gl) override;
  void draw_surfaces(const render::SurfacePass& pass, const World& world,
                     const render::DrawOptions& options) override;
  bool has_markers(const render::DrawOptions& options) const override;
  void draw_markers(const render::PointPass& pass, const World& world,
                    const render::DrawOptions& options) override;
  long dot_count(const World& world) const override;

 private:
  std::vector<ClothSurface> surfaces_;
  std::vector<MovingSphere> spheres_;
  std::vector<render::GpuMesh> surface_gpu_, sphere_gpu_;
  render::GpuMesh pins_gpu_;  // indices of the pinned particles into the particle positions
  std::vector<std::uint32_t> pin_indices_;
};

/// The registered view of the cloth kind.
const render::BodyView& body_view();
/// Its live controls in jelly-lab (keys 1–4, arrows, S; the Cloth panel section): library
/// jelly_cloth_view_controls, which only jelly-lab links.
std::unique_ptr<render::BodyControls> make_controls();

}  // namespace jelly::cloth_view
