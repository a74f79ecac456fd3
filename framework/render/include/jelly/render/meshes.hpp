// Draw proxies built on the CPU from the physics' own numbers (house style §3): the renderer only
// uploads these. No GL here, so tests check the geometry without a context.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

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

/// Segments around circles (hole, bowl, sphere terrain). With 256 segments a chord lies at most
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

/// Appends the two triangles (a, b, c) and (a, c, d) of a quad.
void add_quad(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d);
/// Vertex normals from the triangles (area-weighted sum of their normals, normalised; +y where a
/// vertex's sum vanishes). The normals must be zero on entry.
void smooth_normals(Mesh& mesh);

/// What a scene shows: each body as its kind's view module frames it (BodyView::frame; the
/// current particles when no kind covers them) plus each terrain's extent (a plane's hole, the
/// bowl's cap, the sphere; a plane without a hole adds only its point).
Bounds scene_bounds(const World& world);

/// Half-size of the drawn square of a plane [m] for a world whose other content is in `b`.
double plane_half_extent(const Bounds& b);

}  // namespace jelly::render
