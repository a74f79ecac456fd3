// Your code: the course integrators, tasks A1.T10–A1.T13.
// Read assignments/a1/handout/T10-explicit-euler.md first. Check yourself with: tools/selfcheck
#include "jelly/a1/integrators.hpp"

namespace jelly::a1 {

void explicit_euler_step(System& system, State& s, double h, Workspace& w) {
  // TODO(A1.T10): x ← x + h v_n, v ← v + h a_n (both from the old state).
  // assignments/a1/handout/T10-explicit-euler.md. system.acceleration(state, a) gives a(x, v).
  (void)system, (void)s, (void)h, (void)w;
}

void implicit_euler_step(System& system, State& s, double h, Workspace& w) {
  // TODO(A1.T11): predictor–corrector: predict with explicit Euler, then step with the
  // derivatives at the predicted state.
  // assignments/a1/handout/T11-implicit-euler.md. Evaluating a() twice at the SAME state is
  // explicit Euler.
  (void)system, (void)s, (void)h, (void)w;
}

void midpoint_step(System& system, State& s, double h, Workspace& w) {
  // TODO(A1.T12): half a step to the midpoint, then a whole step with the midpoint's derivatives.
  // assignments/a1/handout/T12-midpoint.md. Careful: 1/2 is 0 in C++ (integer division); write h
  // / 2.0.
  (void)system, (void)s, (void)h, (void)w;
}

void rk4_step(System& system, State& s, double h, Workspace& w) {
  // TODO(A1.T13): classical fourth-order Runge–Kutta on (x, v).
  // assignments/a1/handout/T13-rk4.md. 1/6 is 0 in C++; each stage starts from the step's start
  // state.
  (void)system, (void)s, (void)h, (void)w;
}

}  // namespace jelly::a1
