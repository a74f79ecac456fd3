#include <Eigen/Geometry>

#include "jelly/bodies/cube/view/cube_view.hpp"

namespace jelly::cube_view {

using render::add_quad;

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
  render::smooth_normals(mesh_);
}

}  // namespace jelly::cube_view
