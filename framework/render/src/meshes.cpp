#include "jelly/render/meshes.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include <Eigen/Geometry>

namespace jelly::render {

namespace {

constexpr double kPi = 3.14159265358979323846;

Eigen::Vector3f f3(const Vec3& v) { return v.cast<float>(); }

void add_quad(Mesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
  m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
}

// Vertex normals from the triangles (area-weighted sum of their normals, normalised; +y where a
// vertex's sum vanishes). The normals must be zero on entry.
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

}  // namespace

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

JellySurface::JellySurface(const CubeLattice& lat) {
  const int n = lat.n();
  Vec3 centre = Vec3::Zero();
  for (Eigen::Index i = 0; i < lat.initial_positions().cols(); ++i)
    centre += lat.initial_positions().col(i);
  centre /= static_cast<double>(lat.particle_count());
  for (int axis = 0; axis < 3; ++axis)
    for (int side : {0, n - 1}) {
      const auto base = static_cast<std::uint32_t>(particle_of_vertex_.size());
      // Grid (a, b) over the two other axes.
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          int ijk[3];
          ijk[axis] = side;
          ijk[(axis + 1) % 3] = a;
          ijk[(axis + 2) % 3] = b;
          particle_of_vertex_.push_back(lat.index(ijk[0], ijk[1], ijk[2]));
        }
      // Wind outwards: compare the first quad's normal with the direction away from the centre.
      const auto pos = [&](std::uint32_t v) {
        return lat.initial_positions().col(particle_of_vertex_[v] - lat.first_index()).eval();
      };
      const Vec3 face_normal = (pos(base + n) - pos(base)).cross(pos(base + 1) - pos(base));
      const bool flip = face_normal.dot(pos(base) - centre) < 0.0;
      for (int a = 0; a + 1 < n; ++a)
        for (int b = 0; b + 1 < n; ++b) {
          const std::uint32_t v00 = base + a * n + b, v10 = v00 + n, v11 = v10 + 1, v01 = v00 + 1;
          if (flip)
            add_quad(mesh_, v00, v01, v11, v10);
          else
            add_quad(mesh_, v00, v10, v11, v01);
        }
    }
  mesh_.positions.resize(particle_of_vertex_.size());
  mesh_.normals.resize(particle_of_vertex_.size());
  Vec3Array x(3, lat.first_index() + lat.particle_count());
  x.rightCols(lat.particle_count()) = lat.initial_positions();
  update(x);
}

void JellySurface::update(const Vec3Array& x) {
  for (std::size_t v = 0; v < particle_of_vertex_.size(); ++v) {
    mesh_.positions[v] = x.col(particle_of_vertex_[v]).cast<float>();
    mesh_.normals[v].setZero();
  }
  smooth_normals(mesh_);
}

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
  // Cubes where they were built (so the framing does not depend on when it is computed); other
  // particles where they are now.
  for (const CubeLattice& c : world.cubes())
    for (Eigen::Index i = 0; i < c.initial_positions().cols(); ++i)
      grow(c.initial_positions().col(i));
  if (world.cubes().empty())
    for (Eigen::Index i = 0; i < x.cols(); ++i) grow(x.col(i));
  // A cloth where it was built, with room below it for its sag (half its side) and around it for
  // its swing (a tenth of its side).
  for (const ClothGrid& c : world.cloths()) {
    const double side = c.spacing() * (c.n() - 1);
    const Vec3 swing = Vec3::Constant(0.1 * side);
    for (Eigen::Index i = 0; i < c.initial_positions().cols(); ++i) {
      const Vec3 p = c.initial_positions().col(i);
      grow(p + swing);
      grow(p - swing - Vec3(0.0, 0.5 * side, 0.0));
    }
  }
  for (int i = 0; i < world.sphere_count(); ++i) {  // cloth scenes
    const SphereBody sb = world.sphere(i);
    grow(sb.center - Vec3::Constant(sb.radius));
    grow(sb.center + Vec3::Constant(sb.radius));
  }
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
