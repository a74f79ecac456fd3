// Your code: the course integrators, tasks A1.T10–A1.T13.
// Read assignments/a1/handout/T10-explicit-euler.md first. Check yourself with: tools/selfcheck
#include "jelly/a1/integrators.hpp"

namespace jelly::a1 {

void explicit_euler_step(System& system, State& s, double h, Workspace& w) {
  // HOSTILE: does not compile.
  s.x += h * s.v
  undeclared_function(s);
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
  // TODO(A1.T13): classical fourth-order Runge–Kutta on (x, v).
  (void)system, (void)s, (void)h, (void)w;
}

}  // namespace jelly::a1
