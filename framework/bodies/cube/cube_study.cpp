// What `jelly study effects` measures on a cube: the cave-in (docs/parameters.md).
#include "cube_study.hpp"

#include <algorithm>

#include <Eigen/Geometry>

#include "jelly/cube_physics.hpp"
#include "jelly/world.hpp"

namespace jelly::bodies {

namespace {

/// The cube's values of a study (BodyStudyValues::values).
enum CubeValue { kRestVolume, kCaveIn, kCaveInFinal, kCubeValues };

/// Volume inside the outer surface of cube `c` (its six faces, each grid quad cut into four
/// triangles at its mean point), by the divergence theorem: Σ m·(a×b)/6. Exact for a cube at rest
/// in any orientation; any closed shape it bends into gets its enclosed (signed) volume.
double cube_volume(const CubeLattice& c, const Vec3Array& x) {
  const int n = c.n();
  const Vec3 o = x.col(c.first_index());  // origin near the body: less rounding
  double six_v = 0.0;
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, d = (a + 2) % 3;
    for (int side : {0, n - 1}) {
      const bool outward = side == n - 1;  // e_b × e_d = e_a points out of the max side
      for (int p = 0; p + 1 < n; ++p)
        for (int q = 0; q + 1 < n; ++q) {
          const int pq[4][2] = {{p, q}, {p + 1, q}, {p + 1, q + 1}, {p, q + 1}};
          Vec3 corner[4];
          for (int m = 0; m < 4; ++m) {
            int g[3];
            g[a] = side;
            g[b] = pq[m][0];
            g[d] = pq[m][1];
            corner[m] = x.col(c.index(g[0], g[1], g[2])) - o;
          }
          const Vec3 mid = 0.25 * (corner[0] + corner[1] + corner[2] + corner[3]);
          for (int m = 0; m < 4; ++m) {
            const Vec3& u = corner[m];
            const Vec3& w = corner[(m + 1) % 4];
            const double t = mid.dot(u.cross(w));
            six_v += outward ? t : -t;
          }
        }
    }
  }
  return six_v / 6.0;
}

/// The cave-in: largest 1 − V(t)/V(0), and V(t)/V(0) now.
class CubeStudy final : public BodyStudy {
 public:
  CubeStudy(const CubeLattice& cube, const State& start) : cube_(cube) {
    v_.values.assign(kCubeValues, BodyStudyValues::kNone);
    rest_volume() = cube_volume(cube_, start.x);
    volume_ = rest_volume();
    v_.values[kCaveIn] = 0.0;
    update();
  }
  void observe(const State& s, const StudyLook&) override {
    volume_ = cube_volume(cube_, s.x);
    v_.values[kCaveIn] = std::max(v_.values[kCaveIn], 1.0 - volume_ / rest_volume());
    update();
  }
  const BodyStudyValues& values() const override { return v_; }

 private:
  double& rest_volume() { return v_.values[kRestVolume]; }
  void update() {
    v_.over_time = volume_ / rest_volume();
    v_.values[kCaveInFinal] = 1.0 - volume_ / rest_volume();
  }
  const CubeLattice& cube_;
  double volume_ = 0.0;
  BodyStudyValues v_;
};

}  // namespace

std::unique_ptr<BodyStudy> make_cube_study(const World& world, const State& start,
                                           const std::vector<std::string>& measures) {
  if (cubes_of(world).empty() ||
      std::find(measures.begin(), measures.end(), "cave_in") == measures.end())
    return nullptr;
  return std::make_unique<CubeStudy>(cubes_of(world).front(), start);
}

const std::vector<BodyMeasure>& cube_measures() {
  static const std::vector<BodyMeasure> measures = {
      {"cave_in",
       MeasurePlace::kLanding,
       "  cave-in      largest 1 - V(t)/V(0) over the run, V = volume inside the cube's outer "
       "surface\n"
       "               (its six faces as triangles); cave-in at end = 1 - V(T)/V(0). Cube "
       "bodies only.\n",
       {{"rest_volume", kRestVolume}, {"cave_in_max", kCaveIn}, {"cave_in_final", kCaveInFinal}},
       {{"cave-in max", kCaveIn, 100.0, "%.1f %%"},
        {"cave-in at end", kCaveInFinal, 100.0, "%.1f %%"}},
       {"cave-in", kCaveIn, 100.0, "%.3g", "%"},
       {"cave_in_%", kCaveIn, 100.0},
       "cave-in: largest volume loss [%]",
       "volume / rest volume"}};
  return measures;
}

}  // namespace jelly::bodies
