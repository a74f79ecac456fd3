#include "jelly/integrator.hpp"

namespace jelly {

std::string_view to_string(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::ExplicitEuler: return "explicit_euler";
    case IntegratorKind::ImplicitEuler: return "implicit_euler";
    case IntegratorKind::Midpoint: return "midpoint";
    case IntegratorKind::RK4: return "rk4";
    case IntegratorKind::SymplecticEuler: return "symplectic_euler";
    case IntegratorKind::BackwardEuler: return "backward_euler";
  }
  return "unknown";
}

std::optional<IntegratorKind> integrator_from_string(std::string_view name) {
  for (IntegratorKind k : kAllIntegrators)
    if (to_string(k) == name) return k;
  return std::nullopt;
}

std::string_view display_name(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::ExplicitEuler: return "Explicit Euler";
    case IntegratorKind::ImplicitEuler: return "Implicit Euler (course predictor-corrector)";
    case IntegratorKind::Midpoint: return "Midpoint";
    case IntegratorKind::RK4: return "RK4";
    case IntegratorKind::SymplecticEuler: return "Symplectic Euler";
    case IntegratorKind::BackwardEuler: return "Backward Euler (CG)";
  }
  return "unknown";
}

int evaluations_per_step(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::ImplicitEuler:
    case IntegratorKind::Midpoint: return 2;
    case IntegratorKind::RK4: return 4;
    default: return 1;
  }
}

void symplectic_euler_step(System& system, State& s, double h, Workspace& w) {
  Vec3Array& a = w.accel[0];
  system.acceleration(s, a);
  s.v += h * a;
  s.x += h * s.v;
}

}  // namespace jelly
