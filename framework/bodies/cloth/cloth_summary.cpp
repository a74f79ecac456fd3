// What a frame of a cloth scene records (cloth contract decision 12).
#include "cloth_summary.hpp"

#include <algorithm>

#include "jelly/cloth_physics.hpp"

namespace jelly::bodies {

ClothFrameSummary summarize_cloth(const World& w, const State& s, double t) {
  ClothFrameSummary out;
  FrameSummary& f = out.cloth;
  f.time = t;
  const ClothPhysics& cloth = cloth_physics(w);
  const Eigen::VectorXd& m = w.masses();
  const Vec3 g = w.gravity().value_or(Vec3::Zero());
  const Eigen::Index n = std::min<Eigen::Index>(cloth.cloth_particle_count(), s.size());
  double total = 0.0;
  out.lowest_y = n > 0 ? s.x(1, 0) : 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    f.com += m[i] * s.x.col(i);
    total += m[i];
    f.max_speed = std::max(f.max_speed, s.v.col(i).norm());
    f.kinetic += 0.5 * m[i] * s.v.col(i).squaredNorm();
    f.potential -= m[i] * g.dot(s.x.col(i));
    out.lowest_y = std::min(out.lowest_y, s.x(1, i));
  }
  if (total > 0.0) f.com /= total;
  f.spring = w.energy(s).spring;
  for (int k = 0; k < cloth.sphere_count(); ++k) {
    const int p = cloth.sphere_particle(k);
    if (p >= 0 && p < s.size()) {  // dynamic: part of the integrated state
      out.sphere_centers.emplace_back(s.x.col(p));
      out.sphere_velocities.emplace_back(s.v.col(p));
    } else {
      const SphereBody b = cloth.sphere(k);
      out.sphere_centers.push_back(b.center);
      out.sphere_velocities.push_back(b.velocity);
    }
  }
  return out;
}

std::string cloth_summary_header(int spheres) {
  std::string out = std::string(kSummaryHeader) + ",lowest_y";
  for (int k = 0; k < spheres; ++k)
    for (const char* c : {"_x", "_y", "_z", "_vx", "_vy", "_vz"})
      out += ",sphere" + std::to_string(k) + c;
  return out;
}

std::vector<double> cloth_summary_row(const ClothFrameSummary& f) {
  const FrameSummary& c = f.cloth;
  std::vector<double> values = {c.time,      c.com.x(), c.com.y(),   c.com.z(), c.kinetic,
                                c.potential, c.spring,  c.max_speed, f.lowest_y};
  for (std::size_t k = 0; k < f.sphere_centers.size(); ++k) {
    for (int d = 0; d < 3; ++d) values.push_back(f.sphere_centers[k][d]);
    for (int d = 0; d < 3; ++d) values.push_back(f.sphere_velocities[k][d]);
  }
  return values;
}

}  // namespace jelly::bodies
