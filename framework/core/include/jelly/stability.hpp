// The stability detector and the stable-step estimate of contract §8.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "jelly/integrator.hpp"
#include "jelly/jacobian.hpp"

namespace jelly {

/// The linearised system's extreme modes and the largest stable step of each integrator.
struct StabilityEstimate {
  double omega_max = 0.0;    ///< largest angular frequency of M⁻¹K at rest [rad/s]
  double damping_max = 0.0;  ///< largest eigenvalue of M⁻¹C at rest [1/s]
  double tau = 0.0;          ///< damping_max / omega_max² [s] (kd/ks for uniform springs)
  double zeta_top = 0.0;     ///< damping ratio of the top mode, τ ω_max / 2
  int power_iterations = 0;  ///< iterations the power method used

  /// Largest step h for which every mode ω ∈ (0, ω_max] of the linearised, uniformly damped
  /// system lies in the integrator's stability region; +inf when every step is stable (backward
  /// Euler, or no springs), 0 when no step is (explicit Euler on an undamped spring).
  double critical_step(IntegratorKind kind) const;
  /// critical_step × safety: the step the framework recommends (safety 0.5, see §8 decisions).
  double recommended_step(IntegratorKind kind) const;
  static constexpr double kSafety = 0.5;
};

/// Estimates ω_max² = λ_max(M⁻¹K) and the damping of the top mode by power iteration on the
/// system's Jacobians at state `at` (normally the rest state at t = 0).
StabilityEstimate estimate_stability(JacobianSystem& system, const State& at);

/// What the detector reports when it stops a run (contract §8).
struct InstabilityReport {
  IntegratorKind integrator = IntegratorKind::ExplicitEuler;
  double step_size = 0.0;         ///< h of the run [s]
  long step = 0;                  ///< the step at which it was detected
  double time = 0.0;              ///< simulated time then [s]
  std::string reason;             ///< "non-finite state", "energy above its start", ...
  double energy_start = 0.0;      ///< [J]
  double energy_now = 0.0;        ///< [J] (NaN when the state is not finite)
  double recommended_step = 0.0;  ///< the estimate's stable step for this integrator [s]
  double critical_step = 0.0;     ///< the estimate's limit before the safety factor [s]

  /// Multi-line text for terminals and the viewer's banner.
  std::string message() const;
};

/// Watches the total energy of a run and flags instability (contract §8):
///  - any position or velocity not finite;
///  - E > E0 + 1 % · E0 + floor;
///  - E growing exponentially: over the last `window` samples every increment is positive and
///    larger than the previous one by at least 20 %, and the total rise exceeds 1e-6 · E0.
class StabilityMonitor {
 public:
  struct Config {
    double relative_margin = 0.01;  ///< fraction of the starting energy
    double absolute_floor = 1e-6;   ///< [J] added to the margin, for scenes starting at E0 ≈ 0
    int sample_every = 10;          ///< steps between energy samples
    int window = 8;                 ///< samples in the exponential-growth window
  };
  StabilityMonitor() = default;
  explicit StabilityMonitor(Config config) : config_(config) {}

  /// Starts watching a run whose energy at t = 0 is e0.
  void start(double e0);
  /// Whether step `step` is a sampling step.
  bool wants_sample(long step) const { return step % config_.sample_every == 0; }
  /// Feeds one sample; returns the reason when unstable, nullopt while stable.
  std::optional<std::string> check(double energy, bool state_finite);
  double start_energy() const { return e0_; }
  const Config& config() const { return config_; }

 private:
  Config config_;
  double e0_ = 0.0;
  std::vector<double> recent_;  ///< the last window + 1 samples (capacity reserved by start())
};

}  // namespace jelly
