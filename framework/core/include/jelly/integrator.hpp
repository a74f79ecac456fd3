// Integrator names and the framework's own integrators (contract §6).
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "jelly/system.hpp"

namespace jelly {

enum class IntegratorKind {
  ExplicitEuler,    ///< student task A1.T10
  ImplicitEuler,    ///< the course's predictor–corrector, student task A1.T11
  Midpoint,         ///< student task A1.T12
  RK4,              ///< student task A1.T13
  SymplecticEuler,  ///< framework: v ← v + h a_n, x ← x + h v(new)
  BackwardEuler,    ///< framework: Baraff & Witkin linearly implicit Euler with CG
};

inline constexpr std::array<IntegratorKind, 6> kAllIntegrators = {
    IntegratorKind::ExplicitEuler, IntegratorKind::ImplicitEuler,   IntegratorKind::Midpoint,
    IntegratorKind::RK4,           IntegratorKind::SymplecticEuler, IntegratorKind::BackwardEuler};

/// CLI/scene name: explicit_euler, implicit_euler, midpoint, rk4, symplectic_euler, backward_euler.
std::string_view to_string(IntegratorKind kind);
/// Parses a name as printed by to_string; nullopt when unknown.
std::optional<IntegratorKind> integrator_from_string(std::string_view name);
/// Human label, e.g. "Implicit Euler (course predictor-corrector)".
std::string_view display_name(IntegratorKind kind);
/// Acceleration evaluations per step (explicit 1, implicit 2, midpoint 2, RK4 4, symplectic 1,
/// backward Euler 1 plus its linear solve).
int evaluations_per_step(IntegratorKind kind);

/// Symplectic (semi-implicit) Euler: v ← v + h a(x, v), then x ← x + h v with the new v.
void symplectic_euler_step(System& system, State& s, double h, Workspace& w);

}  // namespace jelly
