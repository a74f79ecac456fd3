// A run's short label on a frame, and the number formats of the frame's texts (the printed
// parameters themselves are jelly/render/captions.hpp's: their body line is the body kind's).
#pragma once

#include <string>

#include "jelly/session/simulation_run.hpp"

namespace jelly::session {

/// `value` printed with one printf conversion (`format`, e.g. "%.3g kg"), for captions.
std::string format_number(const char* format, double value);
/// A time step for a caption: "1 ms", "250 us".
std::string step_text(double h);
/// Compact label of one view in comparison mode: "RK4   h = 1 ms   4 evals/step   0.84 ms/step"
/// on one line, and the run's own parameters (`key=value; …`) on a second line when it has any.
std::string run_label(const SimulationRun& run);

}  // namespace jelly::session
