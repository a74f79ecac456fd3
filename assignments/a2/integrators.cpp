// Your code: the course integrators, tasks A2.T8–A2.T11.
// Read assignments/a2/handout/T8-explicit-euler.md first. Check yourself with: tools/selfcheck
#include "jelly/a2/integrators.hpp"

namespace jelly::a2 {

void explicit_euler_step(System& system, State& s, double h, Workspace& w) {
  // TODO(A2.T8): x ← x + h v_n, v ← v + h a_n (both from the old state).
  // assignments/a2/handout/T8-explicit-euler.md. system.acceleration(state, a) gives a(x, v).
  (void)system, (void)s, (void)h, (void)w;
}

void implicit_euler_step(System& system, State& s, double h, Workspace& w) {
  // TODO(A2.T9): predictor–corrector: predict with explicit Euler, then step with the
  // derivatives at the predicted state.
  // assignments/a2/handout/T9-implicit-euler.md. Evaluating a() twice at the SAME state is
  // explicit Euler.
  (void)system, (void)s, (void)h, (void)w;
}

void midpoint_step(System& system, State& s, double h, Workspace& w) {
  // TODO(A2.T10): half a step to the midpoint, then a whole step with the midpoint's derivatives.
  // assignments/a2/handout/T10-midpoint.md. Careful: 1/2 is 0 in C++ (integer division); write h
  // / 2.0.
  (void)system, (void)s, (void)h, (void)w;
}

void rk4_step(System& system, State& s, double h, Workspace& w) {
  // TODO(A2.T11): classical fourth-order Runge–Kutta on (x, v).
  // assignments/a2/handout/T11-rk4.md. 1/6 is 0 in C++; each stage starts from the step's start
  // state.
  (void)system, (void)s, (void)h, (void)w;
}

}  // namespace jelly::a2
