// The parameter study behind `jelly study effects`: one declared parameter (or the integrator)
// swept over given values, and per run what a student sees when the jelly lands — the impact,
// the bounce, the cave-in, when it comes to rest, the energy lost — and what the run cost.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "jelly/body_kind.hpp"
#include "jelly/integrator.hpp"
#include "jelly/scene.hpp"

namespace jelly::cli::study {

/// A linked body kind's measure (BodyKindModule::measures), with the kind that takes it.
struct KindMeasure {
  const BodyKindModule* kind;
  const BodyMeasure* measure;
};

/// Every linked kind's measures, in the order of the kinds and of their lists.
std::vector<KindMeasure> kind_measures();

/// The measures the framework knows, by the names an assignment's manifest lists under
/// [studies] measures (docs/parameters.md, "What is measured"): its own (impact, bounce, rest,
/// energy) and every linked kind's, the landing ones after the bounce and the others after the
/// energy. The cost and the stability of every run are always reported.
std::vector<std::string> known_measures();

/// Which measures a study computes and reports.
struct Measures {
  bool impact = true;  ///< first contact and the centre-of-mass speed just before it
  bool bounce = true;  ///< the turn, the peak speed and the bounce after it
  bool rest = true;    ///< when the body comes to rest
  bool energy = true;  ///< energy at start and end, and what was lost
  /// The body kinds' own measures that are on, by name (BodyKindModule::measures); NaN in a
  /// scene whose kind does not take them.
  std::vector<std::string> kinds;
  /// Whether the kind's measure `name` is on.
  bool has(std::string_view name) const;
};

/// The measures `names` lists (a manifest's [studies] measures; `manifest` names the file in
/// errors). Throws std::invalid_argument naming the manifest and the key for an unknown name.
Measures measures_from(const std::vector<std::string>& names, const std::string& manifest);

/// What to sweep and how to measure it (plain data: the command line only fills it in).
struct EffectsOptions {
  /// The swept key as `jelly params` lists it; '*' stands for one dotted part
  /// ("springs.*.ks" sets every spring type the scene has; "sphere.*.radius" every sphere), and
  /// ".x"/".y"/".z" after a vector key sets one component ("body.center.y" is the drop height).
  /// Empty: only integrators are swept.
  std::string key;
  std::vector<std::string> values;          ///< the key's values, as text (set_parameter's forms)
  std::vector<IntegratorKind> integrators;  ///< one run per integrator and value (integrator-major)
  double duration = 10.0;                   ///< simulated time per run [s]
  double rest_speed = 0.3;                  ///< "at rest": every particle slower than this [m/s]
  double rest_hold = 0.5;                   ///< ... for at least this long, up to the end [s]
  double series_dt = 1.0 / 60.0;            ///< interval of the time series samples [s]
  int repeats = 1;                          ///< timing: median wall time over this many runs
  Measures measures;                        ///< what to measure (the scene's assignment's list)
};

/// What one run measured (definitions: docs/parameters.md, "What is measured").
struct EffectsRow {
  IntegratorKind integrator = IntegratorKind::ExplicitEuler;
  std::string value;  ///< the swept value as given ("" when only integrators are swept)
  double h = 0.0;     ///< step [s]
  long particles = 0;
  long springs = 0;
  double contact_time =
      -1.0;  ///< first step with a collision response or contact force [s]; NaN: none
  double impact_speed = 0.0;  ///< centre-of-mass speed just before it [m/s]
  double turn_time = 0.0;     ///< first time after contact the centre of mass stops descending [s]
  double peak_speed = 0.0;    ///< largest centre-of-mass speed from turn_time on [m/s]
  double com_apex = 0.0;      ///< highest centre of mass (along −g) from turn_time on [m]
  double bounce = 0.0;        ///< com_apex − centre-of-mass height at turn_time [m]
  double rest_time =
      0.0;  ///< start of the final stretch of rest (rest_speed, rest_hold) [s]; NaN: never
  const BodyKindModule* kind = nullptr;  ///< the scene's body kind
  std::vector<double> kind_values;       ///< what its study measured (BodyStudyValues::values)
  double energy_start = 0.0;             ///< kinetic + gravitational + spring at t = 0 [J]
  double energy_end = 0.0;               ///< the same at the end [J]
  bool stable = true;         ///< the §8 detector never fired (the run stops when it does)
  bool finite = true;         ///< the state stayed finite
  double detected_at = -1.0;  ///< when the detector fired [s]; −1 when it did not
  std::string reason;         ///< the detector's reason
  double sim_time = 0.0;      ///< simulated time covered [s]
  double wall = 0.0;          ///< wall time of the steps only, median over repeats [s]
  long evaluations = 0;       ///< acceleration (force) evaluations
  long cg_iterations = 0;     ///< backward Euler's CG iterations
  double dissipated() const { return energy_start - energy_end; }
  double wall_per_sim() const { return sim_time > 0.0 ? wall / sim_time : 0.0; }
  /// Column `c` of the kind's measure `m` as shown: its scaled value, NaN when the scene's kind
  /// is another or did not measure it.
  double shown(const KindMeasure& m, const BodyMeasureColumn& c) const;
};

/// Samples of one run over time, every series_dt (for the time plots).
struct EffectsSeries {
  std::vector<double> t, com_height, com_speed, volume_ratio, max_speed, energy;
};

struct EffectsResult {
  std::string scene_name;
  std::string scene_file;
  std::vector<std::string> keys;  ///< the declared keys the swept key stands for
  EffectsOptions options;
  std::vector<EffectsRow> rows;         ///< integrator-major, values in the order given
  std::vector<EffectsSeries> series;    ///< one per row
  std::string load_before, load_after;  ///< /proc/loadavg at start and end
};

/// Checks every value against the declarations (unknown key with a suggestion, bad value, a
/// vector value split by ',') and returns the scene of each; throws std::invalid_argument with
/// the message. Nothing is simulated.
std::vector<SceneSpec> effects_scenes(const SceneSpec& scene, const EffectsOptions& options,
                                      std::vector<std::string>* keys = nullptr);

/// Runs the sweep; one progress line per run goes to `progress` unless null.
/// Throws std::invalid_argument for bad options or values.
EffectsResult run_effects(const SceneSpec& scene, const EffectsOptions& options,
                          std::FILE* progress);

/// Writes PREFIX.csv, PREFIX.md, PREFIX.dat/.gp/.svg/.png (each measure against the swept value)
/// and PREFIX-time.dat/.gp/.svg/.png (centre-of-mass height, volume and speed over time).
/// Returns the files written; gnuplot problems go to `note`.
std::vector<std::filesystem::path> write_effects(const EffectsResult& r, const std::string& prefix,
                                                 const std::string& title, std::string& note);

}  // namespace jelly::cli::study
