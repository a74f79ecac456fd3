// Runs a hard case and watches what contract §8 and the issue ask of a stable run.
#pragma once

#include <optional>
#include <string>

#include "jelly/scene.hpp"
#include "jelly/simulator.hpp"

namespace jelly::hard {

/// What theory predicts for a step h: stable at or below the recommended step (half the
/// linearised limit), unstable clearly above the limit (> 1.1×, where the worst mode e-folds in a
/// few steps), and either in between (contact can move the limit; the detector must then say so).
enum class Expect { Stable, Unstable, Either };
Expect predict(const StabilityEstimate& e, IntegratorKind kind, double h);
const char* to_string(Expect e);

/// What happened in one run.
struct Outcome {
  bool stopped = false;  ///< the detector stopped the run
  std::optional<InstabilityReport> report;
  double time = 0.0;  ///< simulated time reached [s]
  long steps = 0;
  bool finite = true;          ///< every state seen was finite
  double energy_start = 0.0;   ///< [J]
  double energy_max = 0.0;     ///< largest total energy seen [J]
  double energy_margin = 0.0;  ///< the detector's allowance above the start [J]
  double max_depth = 0.0;      ///< deepest particle below a terrain it is inside the extent of [m]
  /// ε + 2 h v_peak + s [m]: one step's travel past the ε band (the velocity response acts at the
  /// start of the next step), plus one lattice spacing s for what a loaded particle sinks under
  /// the course's velocity-only response (contract §5's known limit: positions are never
  /// corrected). Deeper would mean a particle passed the layer above it: the lattice folded
  /// through the surface.
  double depth_bound = 0.0;
  double v_peak = 0.0;          ///< largest particle speed seen [m/s]
  std::string summary() const;  ///< one line for logs and docs
};

/// Loads scenes/hard/<name>.toml (fails the test when it does not load).
SceneSpec load_hard_scene(const std::string& name);
/// Runs `scene` with `kind` at step h for `horizon` seconds with the §8 detector on, checking
/// energy, finiteness, speed and depth after every step.
Outcome run_case(const SceneSpec& scene, IntegratorKind kind, double h, double horizon);
/// The estimate of contract §8 on the scene's initial state.
StabilityEstimate estimate_for(const SceneSpec& scene);

}  // namespace jelly::hard
