// Reference: the spring and damper forces (physics contract §2). Not shipped to students.
// The World of the reference uses the fast spring engine (spring_engine.cpp) instead of the
// framework's loop (jelly/spring_pass.hpp); both apply these two functions.
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
#include "jelly/JELLY_TASKS_NAMESPACE/forces.hpp"

namespace jelly::JELLY_TASKS_NAMESPACE {

Vec3 spring_force(const Vec3& xa, const Vec3& xb, double ks, double rest_length,
                  double degenerate_length) {
  const Vec3 d = xa - xb;
  const double length = d.norm();
  if (length < degenerate_length || length == 0.0) return Vec3::Zero();
  const Vec3 u = d * (1.0 / length);  // one division instead of three
  return (-ks * (length - rest_length)) * u;
}

Vec3 damper_force(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, double kd,
                  double degenerate_length) {
  const Vec3 d = xa - xb;
  const double length = d.norm();
  if (length < degenerate_length || length == 0.0) return Vec3::Zero();
  const Vec3 u = d * (1.0 / length);
  return (-kd * (va - vb).dot(u)) * u;
}

}  // namespace jelly::JELLY_TASKS_NAMESPACE
