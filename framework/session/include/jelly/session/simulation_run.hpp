// Runs the viewer and `jelly render` show: a scene with one integrator and step, advanced by the
// Simulator's fixed step (never inside a draw call), with a history for plots. No GL: a front end
// hangs its own per-world data (the renderer's draw proxies) on a run as a RunAttachment.
#pragma once

#include <deque>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "jelly/auto_step.hpp"
#include "jelly/scene.hpp"
#include "jelly/simulator.hpp"

namespace jelly::session {

/// What one run simulates: the scene as edited, the integrator and the step size (the cap of the
/// automatic step when the scene sets simulation.auto_dt).
struct RunSetup {
  SceneSpec scene;
  IntegratorKind integrator = IntegratorKind::ExplicitEuler;
  double dt = 0.001;  ///< [s]
  /// Parameters this run changes from the shared scene ("key=value; …", shown in its label).
  std::string overrides;
  /// From the scene's own simulation settings.
  static RunSetup from_scene(const SceneSpec& scene) {
    return {scene, scene.integrator, scene.dt, {}};
  }
};

/// One sample of a run's history (plots).
struct RunSample {
  double time = 0.0;         ///< [s]
  double energy = 0.0;       ///< total [J]
  double kinetic = 0.0;      ///< [J]
  double com_height = 0.0;   ///< mass-weighted mean y [m]
  double ms_per_step = 0.0;  ///< wall time per step, averaged over the frame [ms]
};

/// Data a front end keeps per run and per world (the renderer's draw proxies, which hold GL
/// objects). The run owns it and drops it whenever it rebuilds its world.
class RunAttachment {
 public:
  virtual ~RunAttachment() = default;
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
  /// The front end's data for the current world (null after reset()).
  RunAttachment* attachment() const { return attachment_.get(); }
  void attach(std::unique_ptr<RunAttachment> a) { attachment_ = std::move(a); }

  /// advance_to records a sample every this many steps (and at its end).
  static constexpr long kSampleEvery = 20;
  /// Most samples kept in history().
  static constexpr std::size_t kHistory = 4000;

 private:
  void record(double ms_per_step);

  RunSetup setup_;
  TaskTable tasks_;
  std::unique_ptr<Simulator> sim_;
  std::unique_ptr<RunAttachment> attachment_;
  std::string error_;
  std::optional<AutoStep> auto_step_;
  double ms_per_step_ = 0.0;
  bool budget_hit_ = false;
  std::deque<RunSample> history_;
};

}  // namespace jelly::session
