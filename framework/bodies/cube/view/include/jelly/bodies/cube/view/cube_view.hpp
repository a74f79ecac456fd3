// The cube's view module (a body kind's GL side, jelly/render/body_view.hpp): the jelly's surface,
// its colour and material, its caption line and its name in the Draw panel.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "jelly/cube.hpp"
#include "jelly/render/body_view.hpp"
#include "jelly/render/meshes.hpp"

namespace jelly::cube_view {

/// The jelly's colour (linear RGB, 0–1); the tests classify pixels with it.
inline const Eigen::Vector3f kJellyColor{0.86f, 0.13f, 0.30f};
/// The jelly: wet and glossy.
inline constexpr render::Material kJellyMaterial{0.45f, 48.0f};

/// The outer faces of one cube lattice as a triangle mesh whose vertices follow the particles.
/// Topology is fixed at construction; update() copies current positions and recomputes normals.
class JellySurface {
 public:
  explicit JellySurface(const CubeLattice& lattice);
  /// Positions from state x (3×N over the whole world), area-weighted vertex normals per face.
  void update(const Vec3Array& x);
  const render::Mesh& mesh() const { return mesh_; }
  /// For each mesh vertex, the particle it follows.
  const std::vector<int>& particles() const { return particle_of_vertex_; }

 private:
  render::Mesh mesh_;
  std::vector<int> particle_of_vertex_;
};

/// The draw proxies of a world's cubes: one surface each, in cubes_of(world) order
/// (jelly/cube_physics.hpp).
class CubeDrawable : public render::BodyDrawable {
 public:
  explicit CubeDrawable(const World& world);
  const std::vector<JellySurface>& surfaces() const { return surfaces_; }

  void update(const World& world, const render::DrawOptions& options) override;
  void create_gpu(const render::Gl& gl, GLuint particle_positions) override;
  void destroy_gpu(const render::Gl& gl) override;
  void draw_surfaces(const render::SurfacePass& pass, const World& world,
                     const render::DrawOptions& options) override;

 private:
  std::vector<JellySurface> surfaces_;
  std::vector<render::GpuMesh> gpu_;
};

/// The registered view of the cube kind.
const render::BodyView& body_view();

}  // namespace jelly::cube_view
