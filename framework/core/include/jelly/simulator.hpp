// The simulator owns time: fixed steps of contract §6, the stability detector, and frames.
#pragma once

#include <functional>
#include <memory>
#include <optional>

#include "jelly/backward_euler.hpp"
#include "jelly/integrator.hpp"
#include "jelly/stability.hpp"
#include "jelly/system.hpp"
#include "jelly/world.hpp"

namespace jelly {

/// Outcome of one step.
enum class StepResult { Ok, Unstable };

/// Counts an integrator's acceleration evaluations (for cost studies): wraps a System.
class CountingSystem : public System {
 public:
  explicit CountingSystem(System& inner) : inner_(inner) {}
  void acceleration(const State& s, Vec3Array& a) override {
    ++evaluations_;
    inner_.acceleration(s, a);
  }
  Eigen::Index particle_count() const override { return inner_.particle_count(); }
  long evaluations() const { return evaluations_; }

 private:
  System& inner_;
  long evaluations_ = 0;
};

/// Advances a World with one integrator and a fixed step h. The viewer, the CLI and the grader all
/// step through this class, so the same scene gives the same bits everywhere.
class Simulator {
 public:
  struct Options {
    Options(IntegratorKind kind = IntegratorKind::ExplicitEuler, double step = 0.001)
        : integrator(kind), dt(step) {}
    IntegratorKind integrator = IntegratorKind::ExplicitEuler;
    double dt = 0.001;  ///< fixed step h [s]
    bool detect_instability = true;
    StabilityMonitor::Config monitor;
  };

  Simulator(std::unique_ptr<World> world, Options options);

  /// One step: collision response, then the integrator (contract §6), then the detector.
  /// After an Unstable result the simulator refuses further steps (see instability()).
  StepResult step();
  /// Steps until simulated time reaches t_end (or instability); returns the last result.
  StepResult run_until(double t_end, const std::function<void(const Simulator&)>& after_step = {});

  World& world() { return *world_; }
  const World& world() const { return *world_; }
  const State& state() const { return world_->state(); }
  double time() const { return static_cast<double>(steps_) * options_.dt; }
  long steps() const { return steps_; }
  const Options& options() const { return options_; }
  /// The stability estimate at t = 0 (computed lazily on first use; cheap power iteration).
  const StabilityEstimate& estimate();
  /// Set once the detector fired.
  const std::optional<InstabilityReport>& instability() const { return instability_; }
  /// Energy of the current state.
  Energy energy() const { return world_->energy(world_->state()); }
  /// What the detector compares with its start: the energy, less the work done on the system
  /// from outside (the world's physics' external_work()). For a study that watches a run with its
  /// own monitor.
  double detector_energy() const { return energy().total() - world_->physics().external_work(); }
  /// The detector's settings for this world (its physics' detector_config).
  const StabilityMonitor::Config& detector_config() const { return monitor_.config(); }
  /// Acceleration evaluations so far.
  long evaluations() const { return world_->counters().acceleration_evaluations; }
  /// Backward Euler's solver statistics (iterations, caps hit); null for other integrators.
  const BackwardEulerSolver* backward_euler() const { return backward_.get(); }

 private:
  void integrate();

  std::unique_ptr<World> world_;
  Options options_;
  StepFunction step_fn_ = nullptr;
  Workspace workspace_;
  std::unique_ptr<BackwardEulerSolver> backward_;
  StabilityMonitor monitor_;
  State initial_state_;
  std::optional<StabilityEstimate> estimate_;
  std::optional<InstabilityReport> instability_;
  long steps_ = 0;
};

}  // namespace jelly
