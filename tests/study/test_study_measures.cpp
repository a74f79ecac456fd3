// The measures of `jelly study effects` come from the scene's assignment's manifest ([studies]
// measures): the names the framework knows, a clear error for one it does not, and outputs with
// only the chosen measures' columns and panels (A1 lists all five: its outputs are unchanged).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "jelly/linked_assignments.hpp"
#include "jelly/session/assignments.hpp"
#include "study_effects.hpp"

namespace jelly::cli::study {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(StudyMeasures, EveryLinkedManifestListsOnlyKnownMeasures) {
  for (const LinkedAssignment& a : linked_assignments())
    EXPECT_NO_THROW(
        measures_from(session::manifest_of(a).study_measures, std::string(a.manifest_path)))
        << a.id;
}

TEST(StudyMeasures, TheNamesChooseTheMeasures) {
  const Measures all = measures_from({"impact", "bounce", "cave_in", "rest", "energy"}, "m.toml");
  EXPECT_TRUE(all.impact && all.bounce && all.has("cave_in") && all.rest && all.energy);
  const Measures some = measures_from({"rest", "impact"}, "m.toml");
  EXPECT_TRUE(some.impact && some.rest);
  EXPECT_FALSE(some.bounce || some.has("cave_in") || some.energy);
  const Measures none = measures_from({}, "m.toml");
  EXPECT_FALSE(none.impact || none.bounce || none.has("cave_in") || none.rest || none.energy);
  EXPECT_TRUE(none.kinds.empty());
}

TEST(StudyMeasures, AnUnknownMeasureNamesTheManifestAndTheKey) {
  try {
    measures_from({"bounce", "volume"}, "assignments/x/assignment.toml");
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("assignments/x/assignment.toml: studies.measures: unknown measure "
                        "\"volume\""),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("impact, bounce, cave_in, rest, energy, sag, swing, sink"),
              std::string::npos)
        << text;
  }
}

TEST(StudyMeasures, TheOutputsHaveOnlyTheChosenMeasures) {
  EffectsResult r;
  r.scene_name = "s";
  r.options.integrators = {IntegratorKind::RK4};
  r.options.measures = measures_from({"rest"}, "m.toml");
  r.rows.resize(1);
  r.rows[0].integrator = IntegratorKind::RK4;
  r.rows[0].h = 0.001;
  r.rows[0].rest_time = 0.5;
  r.rows[0].sim_time = 1.0;
  r.series.resize(1);
  r.series[0].t = {0.0, 1.0};
  r.series[0].com_height = r.series[0].com_speed = r.series[0].volume_ratio = {0.0, 0.0};
  r.series[0].max_speed = r.series[0].energy = {0.0, 0.0};
  const fs::path dir = fs::path(JELLY_BINARY_DIR) / "artifacts" / "study-measures";
  fs::remove_all(dir);
  std::string note;
  write_effects(r, (dir / "only-rest").string(), "t", note);
  const std::string csv = read(dir / "only-rest.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "scene,key,value,integrator,h,particles,springs,stable,finite,detected_at,rest_time,"
            "sim_s,force_evaluations,cg_iterations,wall_s,wall_s_per_sim_s,reason");
  const std::string md = read(dir / "only-rest.md");
  EXPECT_NE(md.find("| h [s] | stable | at rest from [s] | wall s / sim s |"), std::string::npos)
      << md;
  EXPECT_EQ(md.find("cave-in"), std::string::npos) << md;
  // Two panels (at rest, wall time) side by side; the time plot without volume and energy.
  const std::string gp = read(dir / "only-rest.gp");
  EXPECT_NE(gp.find("set multiplot layout 1,2"), std::string::npos) << gp;
  EXPECT_EQ(gp.find("cave-in"), std::string::npos) << gp;
  const std::string tgp = read(dir / "only-rest-time.gp");
  EXPECT_EQ(tgp.find("volume"), std::string::npos) << tgp;
  EXPECT_EQ(tgp.find("energy"), std::string::npos) << tgp;
}

}  // namespace
}  // namespace jelly::cli::study
