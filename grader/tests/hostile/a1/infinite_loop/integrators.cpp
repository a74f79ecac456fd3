// Your code: the course integrators, tasks A1.T10–A1.T13.
// Read assignments/a1/handout/T10-explicit-euler.md first. Check yourself with: tools/selfcheck
#include "jelly/a1/integrators.hpp"

namespace jelly::a1 {

void explicit_euler_step(System& system, State& s, double h, Workspace& w) {
  // TODO(A1.T10): x ← x + h v_n, v ← v + h a_n (both from the old state).
  (void)system, (void)s, (void)h, (void)w;
}

void implicit_euler_step(System& system, State& s, double h, Workspace& w) {
  // TODO(A1.T11): predictor–corrector: predict with explicit Euler, then step with the
  // derivatives at the predicted state.
  (void)system, (void)s, (void)h, (void)w;
}

void midpoint_step(System& system, State& s, double h, Workspace& w) {
  // TODO(A1.T12): half a step to the midpoint, then a whole step with the midpoint's derivatives.
  (void)system, (void)s, (void)h, (void)w;
}

void rk4_step(System& system, State& s, double h, Workspace& w) {
  // HOSTILE: never returns.
  for (volatile long i = 0;; i = i + 1) {
  }
  (void)system, (void)s, (void)h, (void)w;
}

}  // namespace jelly::a1
