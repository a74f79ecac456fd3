// Automatic step size: derive a stable step for an integrator from the scene's linearised system
// (the estimate of contract §8) and sub-step each frame as needed.
#pragma once

#include <string>

#include "jelly/integrator.hpp"
#include "jelly/jacobian.hpp"
#include "jelly/stability.hpp"

namespace jelly {

/// What the automatic step size chose, and why.
struct AutoStep {
  double chosen_h = 0.0;           ///< the step to run with [s]; frame_dt / substeps_per_frame
  int substeps_per_frame = 1;      ///< steps per frame (≥ 1)
  double frame_dt = 0.0;           ///< the frame interval the steps divide [s]
  double critical_step = 0.0;      ///< the estimate's limit for this integrator [s] (+inf: none)
  double recommended_step = 0.0;   ///< critical_step × the estimate's safety factor [s]
  double max_step = 0.0;           ///< the cap the caller gave (the scene's dt) [s]
  bool stable_step_exists = true;  ///< false: no step keeps this integrator stable (undamped
                                   ///< springs with explicit Euler or midpoint); h = the cap
  std::string reason;              ///< one line a student understands: what bound the choice

  /// "auto step: h = 0.000521 s (32 substeps per 0.0167 s frame): ..." for terminals.
  std::string message() const;
};

/// Chooses the step: the largest h = frame_dt / k (k a whole number ≥ 1) with h ≤ max_step and
/// h ≤ estimate.recommended_step(kind) (half the linearised limit, since contact stiffens the
/// body). frame_dt > 0 and max_step > 0 are required (std::invalid_argument otherwise).
AutoStep choose_step(const StabilityEstimate& estimate, IntegratorKind kind, double frame_dt,
                     double max_step);

/// The same, estimating the system's extreme modes at state `at` first (power iteration on its
/// Jacobians; the rest state at t = 0 is what contract §8 prescribes).
AutoStep choose_step(JacobianSystem& system, const State& at, IntegratorKind kind, double frame_dt,
                     double max_step);

}  // namespace jelly
