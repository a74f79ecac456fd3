#include "app.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <sstream>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "jelly/session/overrides.hpp"

namespace jelly::app {

namespace fs = std::filesystem;
using namespace jelly::render;
using namespace jelly::session;

std::vector<SimulationRun*> AppState::run_pointers() const {
  std::vector<SimulationRun*> out;
  for (const auto& r : runs) out.push_back(r.get());
  return out;
}

bool load_scene_into(AppState& s, int index, const std::string& path) {
  SceneResult r;
  if (index >= 0 && index < static_cast<int>(s.scenes.size())) r = load_entry(s.scenes[index]);
  else r = resolve_scene(path, s.scenes_dir);
  if (!r) {
    s.scene_error = r.error->text();
    return false;
  }
  s.scene_error.clear();
  s.scene_index = index;
  s.original = *r.scene;
  s.edited = s.original;
  s.integrator = s.original.integrator;
  s.dt = s.original.dt;
  s.camera_reset_requested = true;
  rebuild_runs(s);
  return true;
}

void rebuild_runs(AppState& s) {
  s.runs.clear();
  const TaskTable tasks = linked_tasks();
  if (s.comparing && s.slots.size() >= 2) {
    for (CompareSlot& slot : s.slots) {
      RunSetup setup{s.edited, slot.integrator, slot.dt, {}};
      const auto error = apply_overrides(setup.scene, slot.overrides);
      slot.error = error ? *error : "";
      if (!error) setup.overrides = slot.overrides;  // else: the shared scene, and the error shows
      s.runs.push_back(std::make_unique<SimulationRun>(setup, tasks));
    }
  } else {
    s.runs.push_back(std::make_unique<SimulationRun>(RunSetup{s.edited, s.integrator, s.dt, {}}, tasks));
  }
  s.clock.restart();
}

namespace {

std::string timestamp() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y%m%d-%H%M%S", std::localtime(&t));
  return buf;
}

bool ffmpeg_available() { return std::system("command -v ffmpeg >/dev/null 2>&1") == 0; }

void finish_recording(AppState& s) {
  s.recording = false;
  std::string msg = std::to_string(s.record_frame) + " frames in " + s.record_dir.string();
  if (s.record_frame > 0 && ffmpeg_available()) {
    const fs::path mp4 = s.record_dir / "video.mp4";
    const std::string cmd = "ffmpeg -loglevel error -y -framerate 30 -i '" +
                            (s.record_dir / "frame_%05d.png").string() +
                            "' -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -pix_fmt yuv420p '" + mp4.string() + "'";
    msg += std::system(cmd.c_str()) == 0 ? ", " + mp4.filename().string() : " (ffmpeg failed)";
  } else if (s.record_frame > 0) {
    msg += " (no ffmpeg: PNG only)";
  }
  s.record_message = msg;
}

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
  out.push_back("Not implemented yet (" + std::to_string(count) + " of 13): " + missing);
  const auto missing_integrator = [&](IntegratorKind k) {
    const char* id = k == IntegratorKind::ExplicitEuler ? "A1.T10"
                     : k == IntegratorKind::ImplicitEuler ? "A1.T11"
                     : k == IntegratorKind::Midpoint    ? "A1.T12"
                     : k == IntegratorKind::RK4         ? "A1.T13" : nullptr;
    if (!id) return false;
    for (const TaskStatus& t : s.tasks)
      if (t.id == id) return !t.implemented;
    return false;
  };
  if (missing_integrator(s.integrator))
    out.push_back(std::string(display_name(s.integrator)) +
                  " is a stub: nothing moves. Pick Symplectic Euler (framework) to watch the jelly fall.");
  return out;
}

}  // namespace

int run_app(const AppOptions& opt) {
  BackendOptions bo;
  bo.name = opt.backend;
  bo.width = opt.width;
  bo.height = opt.height;
  bo.title = "Jelly Lab";
  bo.vsync = opt.benchmark == 0 && !opt.smoke_test;
  BackendResult created = create_backend(bo);
  if (!created.backend) {
    std::cerr << "jelly-lab: " << created.error
              << "\n(no display? use `jelly-lab --headless SCENE --frames DIR`)\n";
    return 1;
  }
  auto* window = dynamic_cast<WindowBackend*>(created.backend.get());
  if (!window) {
    std::cerr << "jelly-lab: no window could be opened (" << created.backend->name()
              << " backend); use `jelly-lab --headless SCENE --frames DIR` to render without a display\n";
    return 1;
  }
  Renderer renderer(window->gl(), opt.samples);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini next to the user's files
  ImGui::StyleColorsDark();
  ImGui::GetStyle().WindowRounding = 0.0f;
  ImGui_ImplGlfw_InitForOpenGL(window->window(), true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  AppState s;
  s.scripted = opt.smoke_test || opt.shot_at >= 0.0;
  s.open_panels = opt.open_panels;
  s.scenes_dir = opt.scenes_dir.empty() ? default_scenes_dir() : opt.scenes_dir;
  s.scenes = list_scenes(s.scenes_dir);
  s.tasks = probe_tasks(linked_tasks());
  s.clock.factor = std::clamp(opt.factor, RealTimeClock::kMinFactor, RealTimeClock::kMaxFactor);
  s.frame.draw.particles = opt.particles;
  if (opt.springs) s.frame.draw.springs = {true, true, true, true};
  int index = -1;
  for (std::size_t i = 0; i < s.scenes.size(); ++i)
    if (s.scenes[i].name == opt.scene || s.scenes[i].name == "builtin:" + opt.scene) index = static_cast<int>(i);
  if (!load_scene_into(s, index, opt.scene)) {
    std::cerr << "jelly-lab: " << s.scene_error << "\n";
    if (s.scenes.empty() || !load_scene_into(s, 0)) return 1;
  }
  if (!opt.integrator.empty()) s.integrator = *integrator_from_string(opt.integrator);
  if (opt.dt > 0.0) s.dt = opt.dt;
  for (const std::string& name : opt.compare) s.slots.push_back(CompareSlot{*integrator_from_string(name), s.dt, {}, {}});
  if (s.slots.empty())
    s.slots = {CompareSlot{IntegratorKind::ExplicitEuler, s.dt, {}, {}}, CompareSlot{IntegratorKind::RK4, s.dt, {}, {}}};
  for (const auto& [k, assignment] : opt.slot_sets) {
    if (k > static_cast<int>(s.slots.size())) {
      std::cerr << "jelly-lab: --slot-set " << k << ":" << assignment << ": there are only " << s.slots.size()
                << " runs (--compare a,b[,c[,d]])\n";
      return 2;
    }
    std::string& o = s.slots[static_cast<std::size_t>(k - 1)].overrides;
    o += (o.empty() ? "" : "; ") + assignment;
    SceneSpec probe = s.edited;
    if (const auto error = apply_overrides(probe, o)) {
      std::cerr << "jelly-lab: --slot-set " << k << ":" << assignment << ": " << *error << "\n";
      return 2;
    }
  }
  s.comparing = !opt.compare.empty();
  rebuild_runs(s);

  // Scripted smoke test: every integrator for 2 s of simulated time, then every scene.
  struct Script {
    std::vector<IntegratorKind> integrators{kAllIntegrators.begin(), kAllIntegrators.end()};
    std::size_t integrator = 0;
    std::size_t scene = 0;
    int scene_frames = 0;
    bool scenes_phase = false;
    int failures = 0;
  } script;
  if (opt.smoke_test) {
    s.integrator = script.integrators[0];
    s.comparing = false;
    rebuild_runs(s);
  }

  using clock = std::chrono::steady_clock;
  auto last = clock::now();
  double fps = 60.0;
  std::vector<double> bench_ms, bench_cpu_ms;
  int exit_code = 0;
  int frame_number = 0;
  bool dragging = false;
  double drag_x = 0.0, drag_y = 0.0;

  while (window->poll()) {
    const auto now = clock::now();
    const double wall_dt = std::chrono::duration<double>(now - last).count();
    last = now;
    if (frame_number++ > 0 && wall_dt > 1e-4) fps = frame_number == 2 ? 1.0 / wall_dt : 0.9 * fps + 0.1 / wall_dt;

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();

    // ---- input (outside ImGui's windows) ----
    if (!io.WantCaptureKeyboard) {
      if (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false)) s.playing = !s.playing;
      if (ImGui::IsKeyPressed(GLFW_KEY_N)) s.step_requested = true;
      if (ImGui::IsKeyPressed(GLFW_KEY_R, false)) s.reset_requested = true;
      if (ImGui::IsKeyPressed(GLFW_KEY_C, false)) s.camera_reset_requested = true;
      if (ImGui::IsKeyPressed(GLFW_KEY_P, false)) s.screenshot_requested = true;
      if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) glfwSetWindowShouldClose(window->window(), GLFW_TRUE);
    }
    if (!io.WantCaptureMouse) {
      if (ImGui::IsMouseClicked(0)) {
        dragging = true;
        drag_x = io.MousePos.x;
        drag_y = io.MousePos.y;
      }
      if (io.MouseWheel != 0.0f) s.camera.zoom(io.MouseWheel);
    }
    if (!ImGui::IsMouseDown(0)) dragging = false;
    if (dragging) {
      s.camera.orbit(io.MousePos.x - drag_x, io.MousePos.y - drag_y);
      drag_x = io.MousePos.x;
      drag_y = io.MousePos.y;
    }

    // ---- simulation: the Simulator's fixed step, driven by the clock (never in a draw call) ----
    if (s.reset_requested) {
      rebuild_runs(s);
      s.reset_requested = false;
    }
    const int w = window->width(), h = window->height();
    const std::vector<SimulationRun*> runs = s.run_pointers();
    if (opt.smoke_test) {
      // 0.25 s of simulated time per frame, no wall clock (reproducible).
      if (!script.scenes_phase) {
        const double t = runs.front()->time() + 0.25;
        runs.front()->advance_to(t);
        if (!runs.front()->ok()) ++script.failures;
        if (runs.front()->time() >= 2.0 - 1e-9 || runs.front()->unstable() || !runs.front()->ok()) {
          std::printf("smoke: %-45s t = %.3f s, %ld steps, %.3f ms/step%s\n",
                      std::string(display_name(s.integrator)).c_str(), runs.front()->time(),
                      runs.front()->simulator() ? runs.front()->simulator()->steps() : 0L,
                      runs.front()->ms_per_step(), runs.front()->unstable() ? " (detector stopped it)" : "");
          if (++script.integrator < script.integrators.size()) {
            s.integrator = script.integrators[script.integrator];
          } else {
            script.scenes_phase = true;
            if (!s.scenes.empty() && !load_scene_into(s, 0)) {
              std::printf("smoke: scene %s failed: %s\n", s.scenes[0].name.c_str(), s.scene_error.c_str());
              ++script.failures;
            }
          }
          rebuild_runs(s);
        }
      } else {
        for (SimulationRun* r : runs) r->advance_to(r->time() + 0.1);
        if (++script.scene_frames >= 3) {
          std::printf("smoke: scene %-35s ok, t = %.2f s\n", s.edited.name.c_str(), runs.front()->time());
          script.scene_frames = 0;
          if (++script.scene < s.scenes.size()) {
            if (!load_scene_into(s, static_cast<int>(script.scene))) {
              std::printf("smoke: scene %s failed: %s\n", s.scenes[script.scene].name.c_str(),
                          s.scene_error.c_str());
              ++script.failures;
            }
          } else {
            // Back to the course scene for the screenshot, a little after the start.
            int course = 0;
            for (std::size_t i = 0; i < s.scenes.size(); ++i)
              if (s.scenes[i].name.find("course-2023") != std::string::npos) { course = static_cast<int>(i); break; }
            load_scene_into(s, course);
            for (SimulationRun* r : s.run_pointers()) r->advance_to(1.5);
            s.screenshot_requested = !opt.screenshot.empty();
            glfwSetWindowShouldClose(window->window(), GLFW_TRUE);
          }
        }
      }
    } else if (opt.shot_at >= 0.0) {
      for (SimulationRun* r : runs) r->advance_to(opt.shot_at);
      if (frame_number > 4) {  // a few frames so ImGui's layout settles
        s.screenshot_requested = true;
        glfwSetWindowShouldClose(window->window(), GLFW_TRUE);
      }
    } else if (s.recording) {
      // Recording: a fixed 1/30 s × factor per frame, so the video plays at the chosen speed.
      const double t = runs.front()->time() + s.clock.factor / 30.0;
      for (SimulationRun* r : runs) r->advance_to(t);
    } else if (s.playing && opt.benchmark == 0) {
      double before = runs.front()->time();
      for (SimulationRun* r : runs) before = std::min(before, r->time());
      const double target = s.clock.target(before, wall_dt);
      const double budget = s.clock.budget_ms / static_cast<double>(runs.size());
      bool hit = false;
      double after = target;
      for (SimulationRun* r : runs) {
        r->advance_to(target, budget);
        hit = hit || r->budget_hit();
        if (!r->unstable() && r->ok()) after = std::min(after, r->time());
      }
      s.clock.reached(before, after, hit);
    }
    if (s.step_requested) {
      for (SimulationRun* r : s.run_pointers()) r->step_once();
      s.step_requested = false;
      s.playing = false;
    }

    // ---- draw ----
    s.panel_width = std::min(420, w / 3);
    s.frame.left_margin = s.panel_width;
    s.frame.hints = task_hints(s);
    const std::vector<SimulationRun*> current = s.run_pointers();
    ensure_drawables(renderer, current);
    if (s.camera_reset_requested && !current.empty() && drawable_of(*current.front())) {
      const auto vps = frame_viewports(static_cast<int>(current.size()), w, h, s.frame.left_margin);
      s.camera = OrbitCamera{};
      s.camera.frame(drawable_of(*current.front())->bounds(), vps.front().aspect());
      s.camera_reset_requested = false;
    }
    draw_panels(s, fps);
    ImGui::Render();
    const auto t0 = clock::now();
    const std::clock_t c0 = std::clock();
    draw_frame(renderer, current, s.camera, s.frame, w, h);
    if (s.recording) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%05d.png", s.record_frame++);
      // Recorded frames show the scene and its printed parameters, not the panels.
      const Image shot = window->read_pixels();
      const std::string err = write_png(s.record_dir / name, crop(shot, s.frame.left_margin, 0, shot.width - s.frame.left_margin, shot.height));
      if (!err.empty()) {
        s.record_message = err;
        s.recording = false;
      }
    }
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (s.screenshot_requested) {
      const fs::path file = !opt.screenshot.empty() ? opt.screenshot : fs::path("jelly-lab-" + timestamp() + ".png");
      const std::string err = write_png(file, window->read_pixels());
      s.screenshot_message = err.empty() ? "saved " + file.string() : err;
      std::printf("%s\n", s.screenshot_message.c_str());
      if (!err.empty()) exit_code = 1;
      s.screenshot_requested = false;
    }
    window->present();
    if (opt.benchmark > 0) {
      bench_ms.push_back(std::chrono::duration<double, std::milli>(clock::now() - t0).count());
      bench_cpu_ms.push_back(1000.0 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
      if (static_cast<int>(bench_ms.size()) >= opt.benchmark + 3) glfwSetWindowShouldClose(window->window(), GLFW_TRUE);
    }
  }
  if (s.recording) finish_recording(s);
  if (opt.benchmark > 0 && bench_ms.size() > 3) {
    std::vector<double> ms(bench_ms.begin() + 3, bench_ms.end());
    std::vector<double> cpu(bench_cpu_ms.begin() + 3, bench_cpu_ms.end());
    std::sort(ms.begin(), ms.end());
    std::sort(cpu.begin(), cpu.end());
    const double median = ms[ms.size() / 2];
    std::printf("backend window, %dx%d, %d samples, %s\nframes %zu: median %.2f ms/frame = %.1f fps "
                "(scene + ImGui + swap; min %.2f, max %.2f ms); median CPU %.2f ms/frame\n",
                window->width(), window->height(), renderer.samples(), window->gl()->describe().c_str(),
                ms.size(), median, 1000.0 / median, ms.front(), ms.back(), cpu[cpu.size() / 2]);
  }
  if (opt.smoke_test && script.failures > 0) {
    std::printf("smoke: %d failure(s)\n", script.failures);
    exit_code = 1;
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  s.runs.clear();  // drawables hold GL objects: free them while the context exists
  return exit_code;
}

/// Recording control used by the panel.
void toggle_recording(AppState& s) {
  if (s.recording) {
    finish_recording(s);
    return;
  }
  s.record_dir = fs::path("recordings") / timestamp();
  s.record_frame = 0;
  s.recording = true;
  s.record_message = "recording to " + s.record_dir.string();
}

}  // namespace jelly::app
