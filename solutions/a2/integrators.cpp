// Reference solution of A2.T8–A2.T11 (the course integrators). Not shipped to students.
#include "jelly/a2/integrators.hpp"

namespace jelly::a2 {

void explicit_euler_step(System& system, State& s, double h, Workspace& w) {
  Vec3Array& a = w.accel[0];
  system.acceleration(s, a);
  s.x += h * s.v;  // uses v_n: v is updated after
  s.v += h * a;
}

void implicit_euler_step(System& system, State& s, double h, Workspace& w) {
  Vec3Array& a0 = w.accel[0];
  Vec3Array& a1 = w.accel[1];
  State& predicted = w.state[0];
  system.acceleration(s, a0);
  predicted.x = s.x + h * s.v;  // predictor: one explicit Euler step
  predicted.v = s.v + h * a0;
  system.acceleration(predicted, a1);  // corrector: derivatives at the predicted state
  s.x += h * predicted.v;
  s.v += h * a1;
}

void midpoint_step(System& system, State& s, double h, Workspace& w) {
  Vec3Array& a0 = w.accel[0];
  Vec3Array& a1 = w.accel[1];
  State& mid = w.state[0];
  system.acceleration(s, a0);
  mid.x = s.x + (h / 2.0) * s.v;
  mid.v = s.v + (h / 2.0) * a0;
  system.acceleration(mid, a1);
  s.x += h * mid.v;
  s.v += h * a1;
}

void rk4_step(System& system, State& s, double h, Workspace& w) {
  Vec3Array& a1 = w.accel[0];
  Vec3Array& a2 = w.accel[1];
  Vec3Array& a3 = w.accel[2];
  Vec3Array& a4 = w.accel[3];
  State& y2 = w.state[0];
  State& y3 = w.state[1];
  State& y4 = w.state[2];
  system.acceleration(s, a1);  // k1 = (v, a1)
  y2.x = s.x + (h / 2.0) * s.v;
  y2.v = s.v + (h / 2.0) * a1;
  system.acceleration(y2, a2);  // k2 = (y2.v, a2)
  y3.x = s.x + (h / 2.0) * y2.v;
  y3.v = s.v + (h / 2.0) * a2;
  system.acceleration(y3, a3);  // k3 = (y3.v, a3)
  y4.x = s.x + h * y3.v;
  y4.v = s.v + h * a3;
  system.acceleration(y4, a4);  // k4 = (y4.v, a4)
  s.x += (h / 6.0) * (s.v + 2.0 * y2.v + 2.0 * y3.v + y4.v);
  s.v += (h / 6.0) * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
}

}  // namespace jelly::a2
