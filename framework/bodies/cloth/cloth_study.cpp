// What `jelly study effects` measures on a cloth (cloth contract decision 12: the cloth, not the
// dynamic spheres that follow it in the state): sag, swing and sink (docs/parameters.md).
#include "cloth_study.hpp"

#include <algorithm>

#include "jelly/cloth_physics.hpp"
#include "jelly/world.hpp"

namespace jelly::bodies {

namespace {

class ClothStudy final : public BodyStudy {
 public:
  ClothStudy(const ClothPhysics& cloth, const State& start, const StudyLook& look, bool sinks)
      : cloth_(cloth), start_(look), sinks_(sinks) {
    v_.sag = v_.sag_final = v_.swing = 0.0;
    if (sinks_) v_.sink = v_.sink_final = sink_depth(start);
  }
  void observe(const State& s, const StudyLook& now) override {
    v_.sag_final = start_.height - now.height;
    v_.sag = std::max(v_.sag, v_.sag_final);
    const Vec3 d = now.com - start_.com;
    v_.swing = std::max(v_.swing, (d - now.up.dot(d) * now.up).norm());
    if (sinks_) {
      v_.sink_final = sink_depth(s);
      v_.sink = std::max(v_.sink, v_.sink_final);
    }
  }
  const BodyStudyValues& values() const override { return v_; }

 private:
  /// The deepest unpinned cloth particle inside a sphere (r − |x − c|), 0 when none is inside.
  double sink_depth(const State& s) const {
    const Eigen::Index body = cloth_.cloth_particle_count();
    double deepest = 0.0;
    for (int k = 0; k < cloth_.sphere_count(); ++k) {
      const int p = cloth_.sphere_particle(k);
      const Vec3 c = p >= 0 ? Vec3(s.x.col(p)) : cloth_.sphere(k).center;
      const double r = cloth_.sphere(k).radius;
      for (Eigen::Index i = 0; i < body; ++i)
        if (!cloth_.is_pinned(static_cast<int>(i)))
          deepest = std::max(deepest, r - (s.x.col(i) - c).norm());
    }
    return deepest;
  }
  const ClothPhysics& cloth_;
  const StudyLook start_;
  const bool sinks_;
  BodyStudyValues v_;
};

}  // namespace

std::unique_ptr<BodyStudy> make_cloth_study(const World& world, const State& start,
                                            const StudyLook& look,
                                            const std::vector<std::string>& measures) {
  const ClothPhysics* cloth = find_cloth_physics(world);
  if (!cloth || cloth->cloths().empty()) return nullptr;
  const bool sinks = cloth->sphere_count() > 0 &&
                     std::find(measures.begin(), measures.end(), "sink") != measures.end();
  return std::make_unique<ClothStudy>(*cloth, start, look, sinks);
}

std::string_view cloth_measure_help(std::string_view measure) {
  if (measure == "sag")
    return "  sag          a cloth: largest drop of its centre of mass (pins included) below its "
           "start [m];\n"
           "               sag at end: the drop at T. In a cloth scene the centre of mass, speeds "
           "and rest\n"
           "               are the cloth's (the spheres are not part of them)\n";
  if (measure == "swing")
    return "  swing        a cloth: largest distance of its centre of mass across g from its start "
           "[m]\n";
  if (measure == "sink")
    return "  sink         a cloth: largest depth r - |x - c| of an unpinned particle inside a "
           "sphere [cm];\n"
           "               sink at end: the same at T\n";
  return "";
}

std::string_view cloth_measure_plot_label(std::string_view measure) {
  if (measure == "sag") return "sag: largest drop of the cloth [m]";
  if (measure == "swing") return "swing: largest sideways move of the cloth [m]";
  if (measure == "sink") return "sink: deepest particle in a sphere [cm]";
  return "";
}

std::string_view cloth_contact_help() { return " (or, in a\n  cloth scene, no impulse acted)"; }

}  // namespace jelly::bodies
