// jelly-lab's drawing: what is prepared before each frame, and the frame times of --benchmark.
#include <algorithm>
#include <cstdio>

#include "app_loop.hpp"

namespace jelly::app {

using namespace jelly::render;
using session::SimulationRun;

namespace {

/// Hint lines for the frame when student tasks are missing.
std::vector<std::string> task_hints(const AppState& s) {
  std::vector<std::string> out;
  std::string missing;
  int count = 0;
  for (const TaskStatus& t : s.tasks)
    if (!t.implemented) {
      missing += (count++ ? ", " : "") + t.id;
    }
  if (count == 0) return out;
  out.push_back("Not implemented yet (" + std::to_string(count) + " of " +
                std::to_string(s.tasks.size()) + "): " + missing);
  // The integrator's TaskTable slot: a student integrator whose task is missing moves nothing.
  const auto missing_integrator = [&](IntegratorKind k) {
    const char* slot = k == IntegratorKind::ExplicitEuler   ? "explicit_euler_step"
                       : k == IntegratorKind::ImplicitEuler ? "implicit_euler_step"
                       : k == IntegratorKind::Midpoint      ? "midpoint_step"
                       : k == IntegratorKind::RK4           ? "rk4_step"
                                                            : nullptr;
    if (!slot) return false;
    for (const TaskStatus& t : s.tasks)
      if (t.slot == slot) return !t.implemented;
    return false;
  };
  if (missing_integrator(s.integrator))
    out.push_back(
        std::string(display_name(s.integrator)) +
        " is a stub: nothing moves. Pick Symplectic Euler (framework) to watch the jelly fall.");
  return out;
}

}  // namespace

void prepare_view(AppState& s, Renderer& renderer, int w, int h) {
  s.panel_width = std::min(420, w / 3);
  s.frame.left_margin = s.panel_width;
  s.frame.hints = task_hints(s);
  const std::vector<SimulationRun*> current = s.run_pointers();
  ensure_drawables(renderer, current);
  if (s.camera_reset_requested && !current.empty() && drawable_of(*current.front())) {
    const auto vps = frame_viewports(static_cast<int>(current.size()), w, h, s.frame);
    s.camera = OrbitCamera{};
    s.camera.frame(drawable_of(*current.front())->bounds(), vps.front().aspect());
    s.camera_reset_requested = false;
  }
}

void FrameTimes::start() {
  t0_ = std::chrono::steady_clock::now();
  c0_ = std::clock();
}

void FrameTimes::stop() {
  ms_.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0_).count());
  cpu_ms_.push_back(1000.0 * static_cast<double>(std::clock() - c0_) / CLOCKS_PER_SEC);
}

void FrameTimes::report(const WindowBackend& window, const Renderer& renderer) const {
  if (ms_.size() <= 3) return;
  std::vector<double> ms(ms_.begin() + 3, ms_.end());
  std::vector<double> cpu(cpu_ms_.begin() + 3, cpu_ms_.end());
  std::sort(ms.begin(), ms.end());
  std::sort(cpu.begin(), cpu.end());
  const double median = ms[ms.size() / 2];
  std::printf(
      "backend window, %dx%d, %d samples, %s\nframes %zu: median %.2f ms/frame = %.1f fps "
      "(scene + ImGui + swap; min %.2f, max %.2f ms); median CPU %.2f ms/frame\n",
      window.width(), window.height(), renderer.samples(), window.gl()->describe().c_str(),
      ms.size(), median, 1000.0 / median, ms.front(), ms.back(), cpu[cpu.size() / 2]);
}

}  // namespace jelly::app
