#include "jelly/session/captions.hpp"

#include <cstdio>

namespace jelly::session {

std::string format_number(const char* format, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, value);
  return buf;
}

std::string step_text(double h) {
  return h >= 1e-3 ? format_number("%.4g ms", h * 1e3) : format_number("%.4g us", h * 1e6);
}

std::string run_label(const SimulationRun& run) {
  const int evals = evaluations_per_step(run.setup().integrator);
  std::string out = std::string(display_name(run.setup().integrator)) +
                    "   h = " + step_text(run.step()) + "   " + std::to_string(evals) +
                    (evals == 1 ? " eval/step" : " evals/step");
  if (run.ms_per_step() > 0.0) out += "   " + format_number("%.3f ms/step", run.ms_per_step());
  if (!run.setup().overrides.empty()) out += "\n" + run.setup().overrides;
  return out;
}

}  // namespace jelly::session
