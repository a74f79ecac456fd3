// jelly-lab's set-up: ImGui on the window, and the first state from the command line.
#include <algorithm>
#include <iostream>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "app_loop.hpp"
#include "jelly/cli_common/exit_codes.hpp"
#include "jelly/session/overrides.hpp"

namespace jelly::app {

using namespace jelly::session;

void init_imgui(render::WindowBackend& window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini next to the user's files
  ImGui::StyleColorsDark();
  ImGui::GetStyle().WindowRounding = 0.0f;
  ImGui_ImplGlfw_InitForOpenGL(window.window(), true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
}

void shutdown_imgui() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

int init_state(AppState& s, const AppOptions& opt) {
  s.scripted = opt.smoke_test || opt.shot_at >= 0.0;
  s.open_panels = opt.open_panels;
  add_body_controls(s);
  s.scenes_dir = opt.scenes_dir.empty() ? default_scenes_dir() : opt.scenes_dir;
  s.scenes = list_scenes(s.scenes_dir);
  s.clock.factor = std::clamp(opt.factor, RealTimeClock::kMinFactor, RealTimeClock::kMaxFactor);
  s.frame.draw.particles = opt.particles;
  if (opt.springs) s.frame.draw.springs = {true, true, true, true};
  const std::string scene = opt.scene.empty() ? default_scene_name() : opt.scene;
  int index = -1;
  for (std::size_t i = 0; i < s.scenes.size(); ++i)
    if (s.scenes[i].name == scene || s.scenes[i].name == "builtin:" + scene)
      index = static_cast<int>(i);
  if (!load_scene_into(s, index, scene)) {
    std::cerr << "jelly-lab: " << s.scene_error << "\n";
    if (s.scenes.empty() || !load_scene_into(s, 0)) return cli::kExitFailure;
  }
  if (!opt.integrator.empty()) s.integrator = *integrator_from_string(opt.integrator);
  if (opt.dt > 0.0) s.dt = opt.dt;
  for (const std::string& name : opt.compare)
    s.slots.push_back(CompareSlot{*integrator_from_string(name), s.dt, {}, {}});
  if (s.slots.empty())
    s.slots = {CompareSlot{IntegratorKind::ExplicitEuler, s.dt, {}, {}},
               CompareSlot{IntegratorKind::RK4, s.dt, {}, {}}};
  for (const auto& [k, assignment] : opt.slot_sets) {
    if (k > static_cast<int>(s.slots.size())) {
      std::cerr << "jelly-lab: --slot-set " << k << ":" << assignment << ": there are only "
                << s.slots.size() << " runs (--compare a,b[,c[,d]])\n";
      return cli::kExitUsage;
    }
    std::string& o = s.slots[static_cast<std::size_t>(k - 1)].overrides;
    o += (o.empty() ? "" : "; ") + assignment;
    SceneSpec probe = s.edited;
    if (const auto error = apply_overrides(probe, o)) {
      std::cerr << "jelly-lab: --slot-set " << k << ":" << assignment << ": " << *error << "\n";
      return cli::kExitUsage;
    }
  }
  s.comparing = !opt.compare.empty();
  rebuild_runs(s);
  return cli::kExitOk;
}

}  // namespace jelly::app
