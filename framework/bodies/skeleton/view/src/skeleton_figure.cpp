// One posture of the skeleton as lit meshes: a cylinder per bone, a sphere per joint (with the
// spheres the cylinders read as capsules), the picked bone apart.
#include <algorithm>
#include <cmath>

#include "jelly/bodies/skeleton/view/skeleton_view.hpp"

namespace jelly::skeleton_view {

namespace {
constexpr double kPi = 3.14159265358979323846;
/// Radii as shares of the figure's size: bones, joints, and the picked bone's thickening.
constexpr double kBoneShare = 0.012, kJointShare = 0.018, kPickedFactor = 1.6;
}  // namespace

using render::add_quad;
using render::Mesh;

SkeletonFigure::SkeletonFigure(double size, int segments)
    : segments_(std::max(3, segments)),
      bone_radius_(kBoneShare * size),
      joint_radius_(kJointShare * size) {
  const int rings = std::max(2, segments_ / 2);
  for (int ring = 0; ring <= rings; ++ring) {
    const double phi = kPi * ring / rings;
    for (int k = 0; k <= segments_; ++k) {
      const double a = 2.0 * kPi * k / segments_;
      sphere_dirs_.emplace_back(
          Vec3(std::sin(phi) * std::cos(a), -std::cos(phi), std::sin(phi) * std::sin(a))
              .cast<float>());
    }
  }
  Mesh unit;
  for (int ring = 0; ring < rings; ++ring)
    for (int k = 0; k < segments_; ++k) {
      const auto i = static_cast<std::uint32_t>(ring * (segments_ + 1) + k);
      add_quad(unit, i, i + segments_ + 1, i + segments_ + 2, i + 1);
    }
  sphere_indices_ = std::move(unit.indices);
}

void SkeletonFigure::add_sphere(Mesh& mesh, const Vec3& center, double radius) const {
  const auto first = static_cast<std::uint32_t>(mesh.positions.size());
  const Eigen::Vector3f c = center.cast<float>();
  const auto r = static_cast<float>(radius);
  for (const Eigen::Vector3f& d : sphere_dirs_) {
    mesh.positions.push_back(c + r * d);
    mesh.normals.push_back(d);
  }
  for (std::uint32_t i : sphere_indices_) mesh.indices.push_back(first + i);
}

/// A cylinder of `radius` from a to b (open at the ends: the joints' spheres close it); nothing
/// for a bone of no length.
void SkeletonFigure::add_cylinder(Mesh& mesh, const Vec3& a, const Vec3& b, double radius) const {
  const Vec3 axis = b - a;
  const double length = axis.norm();
  if (!(length > 1e-12)) return;
  Vec3 u, w;
  render::plane_basis(axis / length, u, w);
  const auto first = static_cast<std::uint32_t>(mesh.positions.size());
  for (int k = 0; k <= segments_; ++k) {
    const double t = 2.0 * kPi * k / segments_;
    const Vec3 n = std::cos(t) * u + std::sin(t) * w;
    for (const Vec3* end : {&a, &b}) {
      mesh.positions.push_back((*end + radius * n).cast<float>());
      mesh.normals.push_back(n.cast<float>());
    }
  }
  for (int k = 0; k < segments_; ++k) {
    const auto i = first + static_cast<std::uint32_t>(2 * k);
    add_quad(mesh, i, i + 2, i + 3, i + 1);
  }
}

void SkeletonFigure::update(const skeleton::BoneFrames& f, const Vec3& offset, int picked) {
  for (Mesh* m : {&bones_, &joints_, &picked_}) {
    m->positions.clear();
    m->normals.clear();
    m->indices.clear();
  }
  for (std::size_t b = 0; b < f.end.size(); ++b) {
    const Vec3 s = f.start[b] + offset, e = f.end[b] + offset;
    if (static_cast<int>(b) == picked)
      add_cylinder(picked_, s, e, kPickedFactor * bone_radius_);
    else
      add_cylinder(bones_, s, e, bone_radius_);
    add_sphere(joints_, e, joint_radius_);
  }
}

}  // namespace jelly::skeleton_view
