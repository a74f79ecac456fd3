// Draw proxies built on the CPU from the physics' own numbers (house style §3): the renderer only
// uploads these. No GL here, so tests check the geometry without a context.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "jelly/cloth.hpp"
#include "jelly/cube.hpp"
#include "jelly/render/camera.hpp"
#include "jelly/terrain.hpp"
#include "jelly/world.hpp"

namespace jelly::render {

/// An indexed triangle mesh (float, for the GPU).
struct Mesh {
  std::vector<Eigen::Vector3f> positions;  ///< [m]
  std::vector<Eigen::Vector3f> normals;    ///< unit, one per position
  std::vector<std::uint32_t> indices;      ///< three per triangle
};

/// Segments around circles (hole, bowl, sphere). With 256 segments a chord lies at most
/// R·(1 − cos(π/256)) ≈ 7.5e-5·R inside its circle; the plane shader also discards fragments
/// inside the hole's exact circle, so the drawn hole radius is the physical one.
inline constexpr int kCircleSegments = 256;

/// A plane drawn as a square of half-size `half_extent` [m]: centred on the hole centre when the
/// plane has a hole (then a polar grid whose inner ring lies exactly on the hole's circle), else
/// centred on the projection of `around` onto the plane.
Mesh plane_mesh(const Plane& plane, const Vec3& around, double half_extent);
/// The bowl: the sphere cap below the rim plane, normals pointing inwards (towards the centre).
/// Its top ring lies exactly at y = rim_height with radius rim_radius().
Mesh bowl_mesh(const Bowl& bowl);
/// The sphere obstacle, normals outwards.
Mesh sphere_mesh(const Sphere& sphere);
/// An orthonormal basis (u, w) of the plane with normal n (u·n = w·n = 0).
void plane_basis(const Vec3& n, Vec3& u, Vec3& w);

/// The outer faces of one cube lattice as a triangle mesh whose vertices follow the particles.
/// Topology is fixed at construction; update() copies current positions and recomputes normals.
class JellySurface {
 public:
  explicit JellySurface(const CubeLattice& lattice);
  /// Positions from state x (3×N over the whole world), area-weighted vertex normals per face.
  void update(const Vec3Array& x);
  const Mesh& mesh() const { return mesh_; }
  /// For each mesh vertex, the particle it follows.
  const std::vector<int>& particles() const { return particle_of_vertex_; }

 private:
  Mesh mesh_;
  std::vector<int> particle_of_vertex_;
};

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
  const Mesh& mesh() const { return mesh_; }
  int n() const { return n_; }
  int first_index() const { return first_; }

 private:
  int n_;
  int first_;
  Mesh mesh_;
};

/// A sphere of a cloth scene drawn where it is now: a unit sphere's directions, moved and scaled
/// by update(). Coarser than sphere_mesh() (it is re-uploaded every frame).
class MovingSphere {
 public:
  MovingSphere();
  void update(const Vec3& center, double radius);
  const Mesh& mesh() const { return mesh_; }

 private:
  std::vector<Eigen::Vector3f> directions_;
  Mesh mesh_;
};

/// What a scene shows: the cubes as built (or the current particles when there is no cube) plus
/// each terrain's extent (a plane's hole, the bowl's cap, the sphere; a plane without a hole adds
/// only its point) and, in a cloth scene, the cloth as built with room below it for its sag (half
/// its side) and around it for its swing (a tenth), and every sphere where it is now.
Bounds scene_bounds(const World& world);

/// Half-size of the drawn square of a plane [m] for a world whose other content is in `b`.
double plane_half_extent(const Bounds& b);

}  // namespace jelly::render
