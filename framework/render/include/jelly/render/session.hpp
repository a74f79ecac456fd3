// Runs the viewer shows: a scene with one integrator and step, advanced by the Simulator's fixed
// step (never inside a draw call), and the clock that maps wall time to simulated time.
#pragma once

#include <deque>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "jelly/auto_step.hpp"
#include "jelly/render/renderer.hpp"
#include "jelly/scene.hpp"
#include "jelly/simulator.hpp"

namespace jelly::render {

/// What one run simulates: the scene as edited, the integrator and the step size (the cap of the
/// automatic step when the scene sets simulation.auto_dt).
struct RunSetup {
  SceneSpec scene;
  IntegratorKind integrator = IntegratorKind::ExplicitEuler;
  double dt = 0.001;  ///< [s]
  /// Parameters this run changes from the shared scene ("key=value; …", shown in its label).
  std::string overrides;
  /// From the scene's own simulation settings.
  static RunSetup from_scene(const SceneSpec& scene) { return {scene, scene.integrator, scene.dt, {}}; }
};

/// Applies "key=value" assignments separated by ';' or new lines (the keys of `jelly params`, as
/// `--set` takes them; values may contain commas, e.g. body.center=-5,11,0) to `scene`. Returns
/// the first error ("springs.shear.ks: …") and leaves the scene unchanged then; blank is fine.
std::optional<std::string> apply_overrides(SceneSpec& scene, std::string_view text);

/// One sample of a run's history (plots).
struct RunSample {
  double time = 0.0;         ///< [s]
  double energy = 0.0;       ///< total [J]
  double kinetic = 0.0;      ///< [J]
  double com_height = 0.0;   ///< mass-weighted mean y [m]
  double ms_per_step = 0.0;  ///< wall time per step, averaged over the frame [ms]
};

/// A scene being simulated: owns the Simulator (and so the World) and its history.
class SimulationRun {
 public:
  SimulationRun(RunSetup setup, TaskTable tasks);
  /// Rebuilds the world from the setup (t = 0).
  void reset();
  /// Replaces the setup and resets.
  void reset(RunSetup setup);
  /// Why the run could not be built (empty when it was).
  const std::string& error() const { return error_; }
  bool ok() const { return sim_ != nullptr; }

  /// Steps while t + h/2 ≤ t_target, or until `budget_ms` of wall time is spent, or the detector
  /// stops the run. Returns the steps taken. Records one history sample when it stepped.
  long advance_to(double t_target, double budget_ms = std::numeric_limits<double>::infinity());
  /// Whether the last advance_to stopped at its wall-time budget short of its target.
  bool budget_hit() const { return budget_hit_; }
  /// Exactly one step (single-step key); records a sample.
  void step_once();

  Simulator* simulator() { return sim_.get(); }
  const Simulator* simulator() const { return sim_.get(); }
  const RunSetup& setup() const { return setup_; }
  /// The step the run uses [s]: setup().dt, or the automatic step when the scene asks for one.
  double step() const { return sim_ ? sim_->options().dt : setup_.dt; }
  /// What the automatic step chose (scene simulation.auto_dt = true; setup().dt is its cap).
  const std::optional<AutoStep>& auto_step() const { return auto_step_; }
  double time() const { return sim_ ? sim_->time() : 0.0; }
  bool unstable() const { return sim_ && sim_->instability().has_value(); }
  /// Smoothed wall time per step [ms] (0 before the first step).
  double ms_per_step() const { return ms_per_step_; }
  const std::deque<RunSample>& history() const { return history_; }
  /// Mass-weighted mean height of the particles [m].
  double com_height() const;
  /// The draw proxies of the current world (rebuilt by reset()).
  SceneDrawable* drawable() { return drawable_.get(); }
  void set_drawable(std::unique_ptr<SceneDrawable> d) { drawable_ = std::move(d); }

  /// advance_to records a sample every this many steps (and at its end).
  static constexpr long kSampleEvery = 20;
  /// Most samples kept in history().
  static constexpr std::size_t kHistory = 4000;

 private:
  void record(double ms_per_step);

  RunSetup setup_;
  TaskTable tasks_;
  std::unique_ptr<Simulator> sim_;
  std::unique_ptr<SceneDrawable> drawable_;
  std::string error_;
  std::optional<AutoStep> auto_step_;
  double ms_per_step_ = 0.0;
  bool budget_hit_ = false;
  std::deque<RunSample> history_;
};

/// Maps wall time to simulated time: each frame asks for factor × wall time more, the runs step
/// towards it within a wall-time budget, and what they could not do is dropped (no spiral of
/// death) and reported: "can't keep up: running at 0.37× real time".
class RealTimeClock {
 public:
  double factor = 1.0;         ///< real-time factor, 0.1–4
  double budget_ms = 40.0;     ///< wall time per frame the simulation may take [ms]
  double max_frame_s = 0.1;    ///< longer frames (window dragged, debugger) count as this [s]

  static constexpr double kMinFactor = 0.1;
  static constexpr double kMaxFactor = 4.0;

  /// Simulated time the runs should reach this frame, given their current time and the wall
  /// time since the last frame [s].
  double target(double sim_time, double wall_dt);
  /// Reports where the (slowest) run got to and whether a run stopped at its wall-time budget
  /// short of the target; updates the achieved factor and behind().
  void reached(double sim_time_before, double sim_time_after, bool budget_hit);
  /// Whether the runs fell short of real time recently (over the last ~second).
  bool behind() const { return behind_; }
  /// Simulated seconds per wall second, smoothed over about a second.
  double achieved_factor() const { return achieved_; }
  /// Forget the history (after pause, reset or a setting change).
  void restart();

 private:
  double wall_dt_ = 0.0;
  double target_ = 0.0;  // simulated time asked for so far [s]
  double achieved_ = 1.0;
  double short_frames_ = 0.0;  // smoothed fraction of frames that fell short
  bool behind_ = false;
  bool fresh_ = true;
};

/// Two to four viewports side by side (1×n; 2×2 for four) filling a w×h frame.
std::vector<Viewport> comparison_layout(int count, int width, int height);

/// The parameters a frame is printed with: scene, integrator, step, time, cube and springs,
/// surface coefficients. Several lines. Without the integrator in comparison mode (each viewport
/// has its own label).
std::string caption(const RunSetup& setup, double time, bool with_integrator = true);
/// Short label for comparison mode: "RK4  h = 1 ms  0.84 ms/step".
std::string run_label(const SimulationRun& run);

}  // namespace jelly::render
