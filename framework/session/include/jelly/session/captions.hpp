// The text printed on a frame: the parameters a run was made with, and a run's short label.
#pragma once

#include <string>

#include "jelly/session/simulation_run.hpp"

namespace jelly::session {

/// The parameters a frame is printed with: scene, integrator, step, time, cube (or cloth: n, L, m,
/// drag, pins) and springs, surface coefficients (or the spheres and their restitution). Four
/// lines. Without the integrator in comparison mode (each viewport
/// has its own label).
std::string caption(const RunSetup& setup, double time, bool with_integrator = true);
/// Compact label of one view in comparison mode: "RK4   h = 1 ms   4 evals/step   0.84 ms/step"
/// on one line, and the run's own parameters (`key=value; …`) on a second line when it has any.
std::string run_label(const SimulationRun& run);

}  // namespace jelly::session
