#include "jelly/render/meshes.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include <Eigen/Geometry>

#include "jelly/render/body_view.hpp"

namespace jelly::render {

namespace {

constexpr double kPi = 3.14159265358979323846;

Eigen::Vector3f f3(const Vec3& v) { return v.cast<float>(); }

}  // namespace

void add_quad(Mesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
  m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
}

void smooth_normals(Mesh& m) {
  for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const std::uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
    const Eigen::Vector3f nrm =
        (m.positions[b] - m.positions[a]).cross(m.positions[c] - m.positions[a]);
    m.normals[a] += nrm;
    m.normals[b] += nrm;
    m.normals[c] += nrm;
  }
  for (auto& nrm : m.normals) {
    const float len = nrm.norm();
    nrm = len > 0.0f && std::isfinite(len) ? Eigen::Vector3f(nrm / len) : Eigen::Vector3f::UnitY();
  }
}

void plane_basis(const Vec3& n, Vec3& u, Vec3& w) {
  // For the floor (n = +y) this gives u = −x, w = +z: grid lines along the world axes.
  const Vec3 helper = std::abs(n.z()) < 0.9 ? Vec3::UnitZ() : Vec3::UnitX();
  u = helper.cross(n).normalized();
  w = n.cross(u).normalized();
}

Mesh plane_mesh(const Plane& p, const Vec3& around, double half) {
  Mesh m;
  const Vec3 n = p.normal.normalized();
  Vec3 u, w;
  plane_basis(n, u, w);
  const Eigen::Vector3f nf = f3(n);
  if (!p.has_hole) {
    const Vec3 c = around - n.dot(around - p.point) * n;
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 1; ++i) {
        m.positions.push_back(f3(c + (2 * i - 1) * half * u + (2 * j - 1) * half * w));
        m.normals.push_back(nf);
      }
    add_quad(m, 0, 1, 3, 2);
    return m;
  }
  // Polar grid from the hole's circle out to the square's boundary. Shading is per fragment, so
  // a few rings suffice (software GL pays per triangle).
  const Vec3 c = p.hole_center - n.dot(p.hole_center - p.point) * n;
  const double r = p.hole_radius;
  half = std::max(half, 1.5 * r);
  constexpr int kRings = 2;
  for (int k = 0; k < kCircleSegments; ++k) {
    const double a = 2.0 * kPi * k / kCircleSegments;
    const double ca = std::cos(a), sa = std::sin(a);
    const double edge = half / std::max(std::abs(ca), std::abs(sa));  // ray to the square
    for (int ring = 0; ring <= kRings; ++ring) {
      const double t = static_cast<double>(ring) / kRings;
      const double rho = ring == 0 ? r : r + t * t * (edge - r);  // denser near the hole
      m.positions.push_back(f3(c + rho * (ca * u + sa * w)));
      m.normals.push_back(nf);
    }
  }
  const auto at = [&](int k, int ring) {
    return static_cast<std::uint32_t>((k % kCircleSegments) * (kRings + 1) + ring);
  };
  for (int k = 0; k < kCircleSegments; ++k)
    for (int ring = 0; ring < kRings; ++ring)
      add_quad(m, at(k, ring), at(k + 1, ring), at(k + 1, ring + 1), at(k, ring + 1));
  return m;
}

Mesh bowl_mesh(const Bowl& b) {
  Mesh m;
  const double cos_rim = std::clamp((b.center.y() - b.rim_height) / b.radius, -1.0, 1.0);
  const double phi_rim = std::acos(cos_rim);  // polar angle from the bottom to the rim
  constexpr int kRings = 16;
  m.positions.push_back(f3(b.center - b.radius * Vec3::UnitY()));
  m.normals.push_back(Eigen::Vector3f::UnitY());
  for (int ring = 1; ring <= kRings; ++ring) {
    const double phi = phi_rim * ring / kRings;
    for (int k = 0; k < kCircleSegments; ++k) {
      const double a = 2.0 * kPi * k / kCircleSegments;
      const Vec3 dir(std::sin(phi) * std::cos(a), -std::cos(phi), std::sin(phi) * std::sin(a));
      Vec3 x = b.center + b.radius * dir;
      if (ring == kRings) x.y() = b.rim_height;  // exactly on the rim plane
      m.positions.push_back(f3(x));
      m.normals.push_back(f3(-dir));
    }
  }
  const auto at = [&](int ring, int k) {
    return static_cast<std::uint32_t>(1 + (ring - 1) * kCircleSegments + (k % kCircleSegments));
  };
  for (int k = 0; k < kCircleSegments; ++k)
    m.indices.insert(m.indices.end(), {0, at(1, k + 1), at(1, k)});
  for (int ring = 1; ring < kRings; ++ring)
    for (int k = 0; k < kCircleSegments; ++k)
      add_quad(m, at(ring, k), at(ring, k + 1), at(ring + 1, k + 1), at(ring + 1, k));
  return m;
}

Mesh sphere_mesh(const Sphere& s) {
  Mesh m;
  constexpr int kRings = 48;
  const int seg = kCircleSegments / 2;
  for (int ring = 0; ring <= kRings; ++ring) {
    const double phi = kPi * ring / kRings;
    for (int k = 0; k <= seg; ++k) {
      const double a = 2.0 * kPi * k / seg;
      const Vec3 dir(std::sin(phi) * std::cos(a), -std::cos(phi), std::sin(phi) * std::sin(a));
      m.positions.push_back(f3(s.center + s.radius * dir));
      m.normals.push_back(f3(dir));
    }
  }
  for (int ring = 0; ring < kRings; ++ring)
    for (int k = 0; k < seg; ++k) {
      const auto i = static_cast<std::uint32_t>(ring * (seg + 1) + k);
      add_quad(m, i, i + seg + 1, i + seg + 2, i + 1);
    }
  return m;
}

Bounds scene_bounds(const World& world) {
  Bounds b;
  const Vec3Array& x = world.state().x;
  bool any = false;
  const auto grow = [&](const Vec3& p) {
    if (!p.allFinite()) return;
    if (!any) b.lo = b.hi = p;
    b.lo = b.lo.cwiseMin(p);
    b.hi = b.hi.cwiseMax(p);
    any = true;
  };
  // Each body as its kind frames it; particles no kind covers where they are now.
  bool covered = false;
  for (const BodyView* view : body_views())
    if (view->present(world)) covered = view->frame(world, grow) || covered;
  if (!covered)
    for (Eigen::Index i = 0; i < x.cols(); ++i) grow(x.col(i));
  for (const Terrain& t : world.terrains()) {
    if (const auto* bowl = std::get_if<Bowl>(&t.shape)) {
      const double rr = bowl->rim_radius();
      grow(bowl->center + Vec3(-rr, -bowl->radius, -rr));
      grow(Vec3(bowl->center.x() + rr, bowl->rim_height, bowl->center.z() + rr));
    } else if (const auto* s = std::get_if<Sphere>(&t.shape)) {
      grow(s->center - Vec3::Constant(s->radius));
      grow(s->center + Vec3::Constant(s->radius));
    } else if (const auto* p = std::get_if<Plane>(&t.shape)) {
      if (p->has_hole) {
        grow(p->hole_center - Vec3(p->hole_radius, 0.0, p->hole_radius));
        grow(p->hole_center + Vec3(p->hole_radius, 0.0, p->hole_radius));
      } else {
        grow(p->point);
      }
    }
  }
  return b;
}

double plane_half_extent(const Bounds& b) { return std::max(20.0, 2.5 * b.radius()); }

}  // namespace jelly::render
