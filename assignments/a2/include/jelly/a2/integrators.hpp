// Student tasks A2.T8–A2.T11: the four course integrators (physics contract §6, the same for the
// cloth: cloth contract §5). Handout: assignments/a2/handout/T8-explicit-euler.md … T11-rk4.md.
//
// Each advances the state `s` by one step h of the system `system`, whose acceleration
// a(x, v) = system.acceleration(state, a) the framework evaluates (gravity, springs, dampers,
// air drag, × inverse mass; 0 for a pinned particle). The collision response of the step already
// ran before these are called. `w` holds preallocated scratch buffers sized for the system; using
// them is optional.
#pragma once

#include "jelly/system.hpp"

namespace jelly::a2 {

/// A2.T8 — Explicit Euler: x ← x + h v_n, v ← v + h a_n, both from the old state.
void explicit_euler_step(System& system, State& s, double h, Workspace& w);

/// A2.T9 — The course's "implicit" Euler: a predictor–corrector, NOT a solve.
/// Predict x̃ = x + h v, ṽ = v + h a_n; then x ← x + h ṽ, v ← v + h a(x̃, ṽ).
void implicit_euler_step(System& system, State& s, double h, Workspace& w);

/// A2.T10 — Midpoint: x_m = x + (h/2) v, v_m = v + (h/2) a_n; then x ← x + h v_m,
/// v ← v + h a(x_m, v_m).
void midpoint_step(System& system, State& s, double h, Workspace& w);

/// A2.T11 — Classical RK4 on y = (x, v), F(y) = (v, a(x, v)):
/// k1 = F(y), k2 = F(y + h/2 k1), k3 = F(y + h/2 k2), k4 = F(y + h k3),
/// y ← y + h/6 (k1 + 2 k2 + 2 k3 + k4).
void rk4_step(System& system, State& s, double h, Workspace& w);

}  // namespace jelly::a2
