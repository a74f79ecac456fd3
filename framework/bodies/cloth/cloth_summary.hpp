// What a frame of a cloth scene records (cloth contract decision 12): `jelly run --summary`'s
// columns and the end-of-run report of a cloth world. Used by the cloth's kind module only.
#pragma once

#include <string>
#include <vector>

#include "jelly/recorder.hpp"
#include "jelly/world.hpp"

namespace jelly::bodies {

/// One recorded frame of a cloth scene: `cloth` is the cloth's own summary (centre of mass of
/// every cloth particle, pinned ones included; the cloth's kinetic and gravitational energy,
/// measured from y = 0; the spring energy; the cloth's largest speed), with the cloth's lowest y
/// and each sphere's centre and velocity beside it, in scene order.
struct ClothFrameSummary {
  FrameSummary cloth;
  double lowest_y = 0.0;                ///< lowest y of any cloth particle [m]
  std::vector<Vec3> sphere_centers;     ///< [m]
  std::vector<Vec3> sphere_velocities;  ///< [m/s]
};

/// Computes the summary of state s of a cloth world w at time t (decision 12).
ClothFrameSummary summarize_cloth(const World& w, const State& s, double t);

/// The `--summary` header of a cloth scene with `spheres` spheres: the columns of
/// kSummaryHeader, then lowest_y, then sphere<i>_x,_y,_z,_vx,_vy,_vz for each sphere.
std::string cloth_summary_header(int spheres);

/// The `--summary` row of `f`: the columns of kSummaryHeader, then cloth_summary_header's.
std::vector<double> cloth_summary_row(const ClothFrameSummary& f);

}  // namespace jelly::bodies
