// The accuracy-against-cost sweep behind `jelly study accuracy`: every integrator over a sweep of
// step sizes, errors against a converged RK4 reference, wall time and force evaluations.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "jelly/integrator.hpp"
#include "jelly/scene.hpp"
#include "jelly/types.hpp"

namespace jelly::cli::study {

/// What to sweep.
struct SweepOptions {
  std::vector<IntegratorKind> integrators;  ///< in plot/table order
  std::vector<double> steps;                ///< step sizes h [s], coarse to fine
  double duration = 1.0;                    ///< simulated time T [s]
  double sample_dt = 0.01;                  ///< error sample interval [s]; a multiple of every h
  int reference_factor = 16;                ///< h_ref = min(steps) / reference_factor (RK4)
  bool check_reference = true;              ///< also run RK4 at h_ref / 2 and compare
  int repeats = 1;                          ///< timing: minimum wall time over this many runs
};

/// One run of one integrator at one step size.
struct RunRow {
  IntegratorKind integrator = IntegratorKind::ExplicitEuler;
  double h = 0.0;             ///< [s]
  bool stable = true;         ///< the §8 detector never fired over the run
  std::string reason;         ///< the detector's reason when it fired
  double detected_at = -1.0;  ///< simulated time when it fired [s]; −1 when it did not
  bool finite = true;         ///< the state stayed finite to the end
  double sim_time = 0.0;      ///< simulated time covered [s] (< T when the state blew up)
  double wall = 0.0;          ///< wall time of the stepping only (minimum over repeats) [s]
  long evaluations = 0;       ///< acceleration (force) evaluations
  long cg_iterations = 0;     ///< backward Euler's CG iterations (sparse mat-vec products)
  double error_rms = 0.0;     ///< RMS over particles and samples of |x − x_ref| [m]
  double error_final = 0.0;   ///< max over particles of |x − x_ref| at T [m]
  double order_rms = 0.0;     ///< observed order from the next coarser h (NaN when none)
  double order_final = 0.0;
  double wall_per_sim() const { return sim_time > 0.0 ? wall / sim_time : 0.0; }
};

/// The reference run and how well it agrees with itself at half its step.
struct ReferenceInfo {
  double h = 0.0;     ///< [s]
  double wall = 0.0;  ///< [s]
  bool checked = false;
  double check_rms = 0.0;    ///< RMS difference RK4(h_ref) − RK4(h_ref/2) [m]
  double check_final = 0.0;  ///< max difference at T [m]
  bool stable = true;
};

struct SweepResult {
  std::string scene_name;
  long particles = 0;
  std::size_t springs = 0;
  std::size_t terrains = 0;
  long first_collision_step = -1;  ///< in the reference run; −1 when none happened
  double first_collision_time = -1.0;
  SweepOptions options;
  ReferenceInfo reference;
  std::vector<RunRow> rows;  ///< integrator-major, steps coarse to fine
  /// Per integrator (in options order): the automatic step `jelly run --auto-dt` would choose
  /// (1/60 s frames, capped at the scene's dt), as "h s (k substeps per frame)".
  std::vector<std::string> auto_steps;
  std::string load_before, load_after;  ///< /proc/loadavg at start and end
};

/// Runs the sweep. Progress lines go to `progress` (stdout) unless null.
/// Throws std::invalid_argument for a sample interval that is not a multiple of a step.
SweepResult run_sweep(const SceneSpec& scene, const SweepOptions& options, std::FILE* progress);

/// Writes PREFIX.csv, PREFIX.md, PREFIX.dat and PREFIX.gp, then runs gnuplot on PREFIX.gp
/// (PREFIX.svg, and PREFIX.png when gnuplot has pngcairo). Returns the files written; a missing
/// gnuplot is reported in `note` (the .gp script is kept so the plot can be made later).
std::vector<std::filesystem::path> write_outputs(const SweepResult& r, const std::string& prefix,
                                                 const std::string& title, std::string& note);

}  // namespace jelly::cli::study
