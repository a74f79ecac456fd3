// What `jelly study effects` measures on a cloth (cloth contract decision 12: the cloth, not the
// dynamic spheres that follow it in the state): sag, swing and sink (docs/parameters.md).
#include "cloth_study.hpp"

#include <algorithm>

#include "jelly/cloth_physics.hpp"
#include "jelly/world.hpp"

namespace jelly::bodies {

namespace {

/// The cloth's values of a study (BodyStudyValues::values).
enum ClothValue { kSag, kSagFinal, kSwing, kSink, kSinkFinal, kClothValues };

class ClothStudy final : public BodyStudy {
 public:
  ClothStudy(const ClothPhysics& cloth, const State& start, const StudyLook& look, bool sinks)
      : cloth_(cloth), start_(look), sinks_(sinks) {
    std::vector<double>& v = v_.values;
    v.assign(kClothValues, BodyStudyValues::kNone);
    v[kSag] = v[kSagFinal] = v[kSwing] = 0.0;
    if (sinks_) v[kSink] = v[kSinkFinal] = sink_depth(start);
  }
  void observe(const State& s, const StudyLook& now) override {
    std::vector<double>& v = v_.values;
    v[kSagFinal] = start_.height - now.height;
    v[kSag] = std::max(v[kSag], v[kSagFinal]);
    const Vec3 d = now.com - start_.com;
    v[kSwing] = std::max(v[kSwing], (d - now.up.dot(d) * now.up).norm());
    if (sinks_) {
      v[kSinkFinal] = sink_depth(s);
      v[kSink] = std::max(v[kSink], v[kSinkFinal]);
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

const std::vector<BodyMeasure>& cloth_measures() {
  static const std::vector<BodyMeasure> measures = {
      {"sag",
       MeasurePlace::kMotion,
       "  sag          a cloth: largest drop of its centre of mass (pins included) below its "
       "start [m];\n"
       "               sag at end: the drop at T. In a cloth scene the centre of mass, speeds "
       "and rest\n"
       "               are the cloth's (the spheres are not part of them)\n",
       {{"sag_max", kSag}, {"sag_final", kSagFinal}},
       {{"sag max [m]", kSag, 1.0, "%.4f"}, {"sag at end [m]", kSagFinal, 1.0, "%.4f"}},
       {"sag", kSag, 1.0, "%.3g", "m"},
       {"sag", kSag},
       "sag: largest drop of the cloth [m]"},
      {"swing",
       MeasurePlace::kMotion,
       "  swing        a cloth: largest distance of its centre of mass across g from its start "
       "[m]\n",
       {{"swing_max", kSwing}},
       {{"swing [m]", kSwing, 1.0, "%.4f"}},
       {"swing", kSwing, 1.0, "%.3g", "m"},
       {"swing", kSwing},
       "swing: largest sideways move of the cloth [m]"},
      {"sink",
       MeasurePlace::kMotion,
       "  sink         a cloth: largest depth r - |x - c| of an unpinned particle inside a "
       "sphere [cm];\n"
       "               sink at end: the same at T\n",
       {{"sink_max", kSink}, {"sink_final", kSinkFinal}},
       {{"sink max [cm]", kSink, 100.0, "%.2f"}, {"sink at end [cm]", kSinkFinal, 100.0, "%.2f"}},
       {"sink", kSink, 100.0, "%.3g", "cm"},
       {"sink_cm", kSink, 100.0},
       "sink: deepest particle in a sphere [cm]"}};
  return measures;
}

std::string_view cloth_contact_help() { return " (or, in a\n  cloth scene, no impulse acted)"; }

}  // namespace jelly::bodies
