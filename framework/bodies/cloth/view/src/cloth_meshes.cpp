#include <cmath>

#include "jelly/bodies/cloth/view/cloth_view.hpp"

namespace jelly::cloth_view {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

using render::add_quad;
using render::smooth_normals;

ClothSurface::ClothSurface(int n, int first_index) : n_(n), first_(first_index) {
  const auto count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  mesh_.positions.assign(count, Eigen::Vector3f::Zero());
  mesh_.normals.assign(count, Eigen::Vector3f::UnitY());
  const auto at = [n](int i, int k) { return static_cast<std::uint32_t>(i * n + k); };
  // Cell (i, k): (i,k), (i,k+1), (i+1,k+1), (i+1,k). For the flat cloth, +z × +x = +y: the
  // triangles wind counter-clockwise seen from above.
  for (int i = 0; i + 1 < n; ++i)
    for (int k = 0; k + 1 < n; ++k)
      add_quad(mesh_, at(i, k), at(i, k + 1), at(i + 1, k + 1), at(i + 1, k));
}

void ClothSurface::update(const Vec3Array& x) {
  for (std::size_t v = 0; v < mesh_.positions.size(); ++v) {
    mesh_.positions[v] = x.col(first_ + static_cast<Eigen::Index>(v)).cast<float>();
    mesh_.normals[v].setZero();
  }
  smooth_normals(mesh_);
}

MovingSphere::MovingSphere() {
  constexpr int kRings = 24, kSegments = 48;
  for (int ring = 0; ring <= kRings; ++ring) {
    const double phi = kPi * ring / kRings;
    for (int k = 0; k <= kSegments; ++k) {
      const double a = 2.0 * kPi * k / kSegments;
      directions_.emplace_back(
          Vec3(std::sin(phi) * std::cos(a), -std::cos(phi), std::sin(phi) * std::sin(a))
              .cast<float>());
    }
  }
  for (int ring = 0; ring < kRings; ++ring)
    for (int k = 0; k < kSegments; ++k) {
      const auto i = static_cast<std::uint32_t>(ring * (kSegments + 1) + k);
      add_quad(mesh_, i, i + kSegments + 1, i + kSegments + 2, i + 1);
    }
  mesh_.normals = directions_;
  mesh_.positions = directions_;
}

void MovingSphere::update(const Vec3& center, double radius) {
  const Eigen::Vector3f c = center.cast<float>();
  const auto r = static_cast<float>(radius);
  for (std::size_t v = 0; v < directions_.size(); ++v) mesh_.positions[v] = c + r * directions_[v];
}

}  // namespace jelly::cloth_view
