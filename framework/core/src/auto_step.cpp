#include "jelly/auto_step.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace jelly {

namespace {

std::string seconds(double h) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g s", h);
  return buf;
}

}  // namespace

std::string AutoStep::message() const {
  char buf[160];
  std::snprintf(buf, sizeof buf,
                "auto step: h = %.6g s (%d substep%s per %.6g s frame): ", chosen_h,
                substeps_per_frame, substeps_per_frame == 1 ? "" : "s", frame_dt);
  return buf + reason;
}

AutoStep choose_step(const StabilityEstimate& estimate, IntegratorKind kind, double frame_dt,
                     double max_step) {
  if (!(frame_dt > 0.0) || !std::isfinite(frame_dt))
    throw std::invalid_argument("choose_step: the frame interval must be a finite number > 0");
  if (!(max_step > 0.0) || !std::isfinite(max_step))
    throw std::invalid_argument("choose_step: the largest step must be a finite number > 0");
  AutoStep a;
  a.frame_dt = frame_dt;
  a.max_step = max_step;
  a.critical_step = estimate.critical_step(kind);
  a.recommended_step = estimate.recommended_step(kind);
  const std::string name(to_string(kind));
  double target = max_step;
  if (!(a.critical_step > 0.0)) {
    a.stable_step_exists = false;
    a.reason = "no step size keeps " + name +
               " stable here (undamped springs sit on the imaginary axis, outside its stability "
               "region); kept the scene's step " +
               seconds(max_step) + " (or a little less, to fit whole substeps into a frame)" +
               " - add damping or choose rk4, symplectic_euler or backward_euler";
  } else if (a.recommended_step < max_step) {
    target = a.recommended_step;
    a.reason = "the estimate's limit for " + name + " is " + seconds(a.critical_step) +
               " (omega_max " +
               [&] {
                 char b[32];
                 std::snprintf(b, sizeof b, "%.4g", estimate.omega_max);
                 return std::string(b);
               }() +
               " rad/s); half of it, " + seconds(a.recommended_step) +
               ", is below the scene's step " + seconds(max_step);
  } else {
    a.reason = std::isinf(a.critical_step)
                   ? name + " is stable at every step; kept the scene's step " + seconds(max_step) +
                         " (or a little less, to fit whole substeps into a frame)"
                   : "the scene's step " + seconds(max_step) + " is within half of " + name +
                         "'s limit " + seconds(a.critical_step);
  }
  // The largest whole number of substeps whose step does not exceed the target. The small
  // relative slack keeps frame_dt / k from exceeding the target by a rounding error only.
  const double k = std::ceil(frame_dt / target * (1.0 - 1e-12));
  if (!(k < static_cast<double>(std::numeric_limits<int>::max())))
    throw std::invalid_argument("choose_step: the stable step " + seconds(target) +
                                " would need more than 2^31 substeps per frame");
  a.substeps_per_frame = std::max(1, static_cast<int>(k));
  a.chosen_h = frame_dt / a.substeps_per_frame;
  return a;
}

AutoStep choose_step(JacobianSystem& system, const State& at, IntegratorKind kind, double frame_dt,
                     double max_step) {
  return choose_step(estimate_stability(system, at), kind, frame_dt, max_step);
}

}  // namespace jelly
