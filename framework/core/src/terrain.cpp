#include <algorithm>
#include <cmath>

#include "jelly/terrain.hpp"
#include "jelly/terrain_geometry.hpp"

namespace jelly {

const SurfaceProperties& Terrain::surface() const {
  return std::visit([](const auto& s) -> const SurfaceProperties& { return s.surface; }, shape);
}

namespace {

// Distance from x to the hole centre measured in the plane.
double in_plane_distance(const Plane& p, const Vec3& x) {
  const Vec3 d = x - p.hole_center;
  return (d - p.normal.dot(d) * p.normal).norm();
}

double horizontal_distance(const Vec3& a, const Vec3& b) {
  const double dx = a.x() - b.x();
  const double dz = a.z() - b.z();
  return std::sqrt(dx * dx + dz * dz);
}

}  // namespace

double signed_distance(const Terrain& t, const Vec3& x) {
  if (const auto* p = std::get_if<Plane>(&t.shape)) return p->normal.dot(x - p->point);
  if (const auto* b = std::get_if<Bowl>(&t.shape)) return b->radius - (x - b->center).norm();
  const auto& s = std::get<Sphere>(t.shape);
  return (x - s.center).norm() - s.radius;
}

Vec3 surface_normal(const Terrain& t, const Vec3& x) {
  if (const auto* p = std::get_if<Plane>(&t.shape)) return p->normal;
  if (const auto* b = std::get_if<Bowl>(&t.shape)) return (b->center - x).normalized();
  const auto& s = std::get<Sphere>(t.shape);
  return (x - s.center).normalized();
}

bool in_extent(const Terrain& t, const Vec3& x) {
  if (const auto* p = std::get_if<Plane>(&t.shape))
    return !p->has_hole || in_plane_distance(*p, x) >= p->hole_radius;
  if (const auto* b = std::get_if<Bowl>(&t.shape))
    return x.y() <= b->rim_height + b->surface.epsilon &&
           horizontal_distance(x, b->center) <= b->rim_radius();
  return true;
}

std::optional<double> lowest_point(const Terrain& t) {
  if (const auto* p = std::get_if<Plane>(&t.shape)) {
    const bool horizontal = std::abs(p->normal.x()) == 0.0 && std::abs(p->normal.z()) == 0.0;
    if (horizontal && !p->has_hole) return p->point.y();
    return std::nullopt;
  }
  if (const auto* b = std::get_if<Bowl>(&t.shape)) return b->center.y() - b->radius;
  return std::nullopt;
}

double min_signed_distance(const Terrain& t, const Vec3& lo, const Vec3& hi) {
  if (const auto* p = std::get_if<Plane>(&t.shape)) {
    // Minimum of a linear function over a box: pick the corner against the normal.
    Vec3 corner;
    for (int d = 0; d < 3; ++d) corner[d] = p->normal[d] >= 0.0 ? lo[d] : hi[d];
    return p->normal.dot(corner - p->point);
  }
  if (const auto* b = std::get_if<Bowl>(&t.shape)) {
    // φ = R − |x − c| is smallest at the box point farthest from c.
    Vec3 far;
    for (int d = 0; d < 3; ++d)
      far[d] = std::abs(lo[d] - b->center[d]) > std::abs(hi[d] - b->center[d]) ? lo[d] : hi[d];
    return b->radius - (far - b->center).norm();
  }
  const auto& s = std::get<Sphere>(t.shape);
  // φ = |x − c| − R is smallest at the box point nearest to c.
  const Vec3 nearest = s.center.cwiseMax(lo).cwiseMin(hi);
  return (nearest - s.center).norm() - s.radius;
}

bool box_outside_extent(const Terrain& t, const Vec3& lo, const Vec3& /*hi*/) {
  if (const auto* b = std::get_if<Bowl>(&t.shape))
    return lo.y() > b->rim_height + b->surface.epsilon;
  return false;
}

}  // namespace jelly
