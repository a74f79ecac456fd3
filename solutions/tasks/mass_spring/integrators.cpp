// Reference: the four course integrators (physics contract §6). Not shipped to students.
//
// Part of the task module mass_spring (solutions/tasks/mass_spring/), named by no assignment: the
// one reference of tasks that several assignments share (same signatures, same contract section).
// The build writes this file out once for each assignment whose manifest lists the module in
// `task_modules` and this file in `files` (cmake/JellyAssignments.cmake, _jelly_module_task_file):
// into build/assignments/<id>/reference/, with the assignment's namespace in place of the word
// below that names it. The copy includes the assignment's own header (a signature that drifted from
// it is a compile error there) and is exactly the file the assignment would hold itself: the
// assignment's reference library compiles it, and the grader grades and mutates it as the
// reference. Each assignment keeps its own stub, header and bindings.
#include "jelly/JELLY_TASKS_NAMESPACE/integrators.hpp"

namespace jelly::JELLY_TASKS_NAMESPACE {

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

}  // namespace jelly::JELLY_TASKS_NAMESPACE
