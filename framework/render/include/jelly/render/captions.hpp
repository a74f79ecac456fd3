// The parameters printed on a frame. Its line about the body is the body kind's (its view
// module's BodyView::caption_body and caption_tail).
#pragma once

#include <string>

#include "jelly/session/simulation_run.hpp"

namespace jelly::render {

/// The parameters a frame is printed with: scene, integrator, step, time, the body (its kind's
/// line) and springs, surface coefficients (and what the kind adds after them), gravity. Four
/// lines. Without the integrator in comparison mode (each viewport has its own label).
std::string caption(const session::RunSetup& setup, double time, bool with_integrator = true);

}  // namespace jelly::render
