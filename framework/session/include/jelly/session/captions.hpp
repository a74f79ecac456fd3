// The text printed on a frame: the parameters a run was made with, and a run's short label.
#pragma once

#include <string>

#include "jelly/session/simulation_run.hpp"

namespace jelly::session {

/// The parameters a frame is printed with: scene, integrator, step, time, cube and springs,
/// surface coefficients. Several lines. Without the integrator in comparison mode (each viewport
/// has its own label).
std::string caption(const RunSetup& setup, double time, bool with_integrator = true);
/// Short label for comparison mode: "RK4  h = 1 ms  0.84 ms/step".
std::string run_label(const SimulationRun& run);

}  // namespace jelly::session
