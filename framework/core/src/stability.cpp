#include "jelly/stability.hpp"

#include "jelly/portable_math.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <vector>

namespace jelly {

namespace {

using Complex = std::complex<double>;

// Largest eigenvalue of the symmetric M^{-1/2} J M^{-1/2} (J = −∂f/∂x or −∂f/∂v) by power
// iteration with a Rayleigh quotient; deterministic start vector.
double power_iteration(const ForceJacobians& jac, bool stiffness, const JacobianSystem& system,
                       int max_iterations, int& used) {
  const Eigen::VectorXd& mass = system.masses();
  const Eigen::Index n = mass.size();
  Eigen::VectorXd inv_sqrt_m = mass.cwiseSqrt().cwiseInverse();
  // A fixed particle (a pin, inverse mass 0) has no mode of its own: the estimate is the free
  // particles'.
  for (Eigen::Index i = 0; i < n; ++i)
    if (system.is_fixed(i)) inv_sqrt_m[i] = 0.0;
  Vec3Array y(3, n), t(3, n), out(3, n);
  std::uint64_t seed = 0x9E3779B97F4A7C15ull;
  for (Eigen::Index i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) {
      seed = seed * 6364136223846793005ull + 1442695040888963407ull;
      y(d, i) = static_cast<double>(seed >> 11) / 9007199254740992.0 - 0.5;
    }
  y /= y.norm();
  double lambda = 0.0;
  used = 0;
  for (int it = 0; it < max_iterations; ++it) {
    for (Eigen::Index i = 0; i < n; ++i) t.col(i) = y.col(i) * inv_sqrt_m[i];
    if (stiffness)
      jac.multiply_dfdx(t, out);
    else
      jac.multiply_dfdv(t, out);
    for (Eigen::Index i = 0; i < n; ++i) out.col(i) *= -inv_sqrt_m[i];  // J = −∂f
    const double rayleigh = (y.array() * out.array()).sum();
    const double norm = out.norm();
    used = it + 1;
    if (!(norm > 0.0)) return 0.0;
    y = out / norm;
    if (it > 20 && std::abs(rayleigh - lambda) <= 1e-9 * std::abs(rayleigh)) {
      lambda = rayleigh;
      break;
    }
    lambda = rayleigh;
  }
  return std::max(lambda, 0.0);
}

// |w| with the core's portable hypot: std::abs of a complex calls the C library's cabs/hypot,
// whose last bits differ between platforms (and so would the critical step found by bisection).
double modulus(Complex w) { return portable::hypot(w.real(), w.imag()); }

// Amplification of one step of a one-stage-in-time method on y' = λy, z = hλ.
double amplification(IntegratorKind kind, Complex z) {
  switch (kind) {
    case IntegratorKind::ExplicitEuler: return modulus(1.0 + z);
    case IntegratorKind::ImplicitEuler: return modulus(1.0 + z + z * z);
    case IntegratorKind::Midpoint: return modulus(1.0 + z + 0.5 * z * z);
    case IntegratorKind::RK4:
      return modulus(1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0);
    default: return 0.0;
  }
}

// Spectral radius of symplectic Euler on x'' = −ω² x − c x'.
double symplectic_radius(double h, double omega, double c) {
  // One-step matrix [[1 − a, h(1 − b)], [−hω², 1 − b]] with a = h²ω², b = hc: trace 2 − a − b,
  // determinant 1 − b. The discriminant tr² − 4 det equals (a + b)² − 4a; computed that way it
  // does not cancel the 4s (which made small steps look unstable through rounding).
  const double a = h * h * omega * omega, b = h * c;
  const double tr = 2.0 - a - b, det = 1.0 - b;
  const double disc2 = (a + b) * (a + b) - 4.0 * a;
  if (disc2 < 0.0) return std::sqrt(std::abs(det));  // complex pair: |λ|² = det
  return 0.5 * (std::abs(tr) + std::sqrt(disc2));
}

bool stable_at(IntegratorKind kind, double h, const std::vector<double>& omegas, double tau) {
  constexpr double kTolerance = 1e-12;
  for (double w : omegas) {
    const double c = tau * w * w;  // damping of the mode: 2ζω with ζ = τω/2
    if (kind == IntegratorKind::SymplecticEuler) {
      if (symplectic_radius(h, w, c) > 1.0 + kTolerance) return false;
      continue;
    }
    // √(c² − 4ω²) as a complex number, written out: libc++'s std::sqrt(complex) goes through
    // polar(), which leaves a rounding residue r·cos(π/2) in the real part of a pure square root.
    const double d = c * c - 4.0 * w * w;
    const Complex disc = d >= 0.0 ? Complex(std::sqrt(d), 0.0) : Complex(0.0, std::sqrt(-d));
    const Complex l1 = (-c + disc) / 2.0, l2 = (-c - disc) / 2.0;
    if (amplification(kind, h * l1) > 1.0 + kTolerance) return false;
    if (amplification(kind, h * l2) > 1.0 + kTolerance) return false;
  }
  return true;
}

}  // namespace

double StabilityEstimate::critical_step(IntegratorKind kind) const {
  const double inf = std::numeric_limits<double>::infinity();
  if (kind == IntegratorKind::BackwardEuler || !(omega_max > 0.0)) return inf;
  if (tau == 0.0) {
    // Undamped: every mode sits on the imaginary axis, where rounding hides the slow growth of
    // explicit Euler (|R|² = 1 + y²) and midpoint (1 + y⁴/4); use the exact intervals instead.
    switch (kind) {
      case IntegratorKind::ExplicitEuler:
      case IntegratorKind::Midpoint: return 0.0;
      case IntegratorKind::ImplicitEuler: return 1.0 / omega_max;  // |1 + iy − y²| ≤ 1 ⇔ |y| ≤ 1
      case IntegratorKind::RK4: return 2.0 * std::sqrt(2.0) / omega_max;
      case IntegratorKind::SymplecticEuler: return 2.0 / omega_max;
      default: return inf;
    }
  }
  std::vector<double> omegas;
  for (int k = 1; k <= 400; ++k) omegas.push_back(omega_max * k / 400.0);
  for (int k = 0; k < 100; ++k)
    omegas.push_back(omega_max * portable::exp10(-4.0 + 4.0 * k / 100.0));
  double lo = 1e-9 / omega_max;
  if (!stable_at(kind, lo, omegas, tau)) return 0.0;
  double hi = 100.0 * std::max(1.0 / omega_max, tau);
  while (stable_at(kind, hi, omegas, tau)) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e6) return inf;
  }
  for (int it = 0; it < 80; ++it) {
    const double mid = 0.5 * (lo + hi);
    (stable_at(kind, mid, omegas, tau) ? lo : hi) = mid;
  }
  return lo;
}

double StabilityEstimate::recommended_step(IntegratorKind kind) const {
  return kSafety * critical_step(kind);
}

StabilityEstimate estimate_stability(JacobianSystem& system, const State& at) {
  StabilityEstimate e;
  ForceJacobians jac;
  jac.reset(system.particle_count(), system.jacobian_pattern());
  system.force_jacobians(at, jac);
  int used_k = 0, used_c = 0;
  const double omega2 = power_iteration(jac, true, system, 2000, used_k);
  e.damping_max = power_iteration(jac, false, system, 2000, used_c);
  e.power_iterations = used_k + used_c;
  e.omega_max = std::sqrt(omega2);
  e.tau = omega2 > 0.0 ? e.damping_max / omega2 : 0.0;
  e.zeta_top = 0.5 * e.tau * e.omega_max;
  return e;
}

std::string InstabilityReport::message() const {
  char buf[1024];
  const std::string stable =
      recommended_step > 0.0 && std::isfinite(recommended_step)
          ? "a step of about " +
                [&] {
                  char b[64];
                  std::snprintf(b, sizeof b, "%.3g s", recommended_step);
                  return std::string(b);
                }()
          : std::string(recommended_step == 0.0
                            ? "no step size (this integrator cannot damp an undamped spring; add "
                              "damping or use rk4, symplectic_euler or backward_euler)"
                            : "any step size");
  std::snprintf(buf, sizeof buf,
                "unstable: %s with h = %g s at step %ld (t = %.4f s): %s.\n"
                "  energy at start %.6g J, now %.6g J.\n"
                "  The linearised system's estimate says this integrator is stable for %s "
                "(limit %.3g s, halved for safety).",
                std::string(display_name(integrator)).c_str(), step_size, step, time,
                reason.c_str(), energy_start, energy_now, stable.c_str(), critical_step);
  return buf;
}

void StabilityMonitor::start(double e0) {
  e0_ = e0;
  recent_.clear();
  // A step never allocates: the window's storage is taken here, once (tests/alloc).
  recent_.reserve(static_cast<std::size_t>(std::max(0, config_.window)) + 2);
}

std::optional<std::string> StabilityMonitor::check(double energy, bool state_finite) {
  if (!state_finite || !std::isfinite(energy)) return "a position or velocity is not finite";
  const double margin = config_.relative_margin * std::abs(e0_) + config_.absolute_floor;
  if (energy > e0_ + margin) {
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "the total energy rose %.3g %% above its start (allowed: %.3g %% plus %.1e J)",
                  e0_ != 0.0 ? 100.0 * (energy - e0_) / std::abs(e0_) : 0.0,
                  100.0 * config_.relative_margin, config_.absolute_floor);
    return std::string(buf);
  }
  recent_.push_back(energy);
  while (static_cast<int>(recent_.size()) > config_.window + 1) recent_.erase(recent_.begin());
  if (static_cast<int>(recent_.size()) == config_.window + 1) {
    bool growing = true;
    double previous = 0.0;
    for (std::size_t k = 1; k < recent_.size() && growing; ++k) {
      const double inc = recent_[k] - recent_[k - 1];
      if (!(inc > 0.0) || (k > 1 && !(inc >= 1.2 * previous))) growing = false;
      previous = inc;
    }
    const double rise = recent_.back() - recent_.front();
    if (growing && rise > 1e-6 * std::abs(e0_) + config_.absolute_floor)
      return std::string("the total energy is growing exponentially");
  }
  return std::nullopt;
}

}  // namespace jelly
