#include "app.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "app_loop.hpp"
#include "jelly/cli_common/exit_codes.hpp"
#include "jelly/session/assignments.hpp"
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

namespace {

// Why this program cannot show `scene`, or "": a kind no linked assignment simulates has no
// tasks to run. (A kind that plays frames is shown too: its build makes a World whose steps play
// them, and its view module draws it.)
std::string why_not_shown(const SceneSpec& scene) {
  try {
    session::assignment_for(scene);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

bool load_scene_into(AppState& s, int index, const std::string& path) {
  SceneResult r;
  if (index >= 0 && index < static_cast<int>(s.scenes.size()))
    r = load_entry(s.scenes[index]);
  else
    r = resolve_scene(path, s.scenes_dir);
  s.scene_not_shown = false;
  if (!r) {
    s.scene_error = r.error->text();
    return false;
  }
  if (std::string why = why_not_shown(*r.scene); !why.empty()) {
    s.scene_error = r.scene->name + ": " + why;
    s.scene_not_shown = true;
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
  const LinkedAssignment& assignment = session::assignment_for(s.edited);
  const TaskTable tasks = assignment.tasks();
  s.tasks = session::probe_assignment(assignment);
  if (s.comparing && s.slots.size() >= 2) {
    for (CompareSlot& slot : s.slots) {
      RunSetup setup{s.edited, slot.integrator, slot.dt, {}};
      const auto error = apply_overrides(setup.scene, slot.overrides);
      slot.error = error ? *error : "";
      if (!error) setup.overrides = slot.overrides;  // else: the shared scene, and the error shows
      s.runs.push_back(std::make_unique<SimulationRun>(setup, tasks));
    }
  } else {
    s.runs.push_back(
        std::make_unique<SimulationRun>(RunSetup{s.edited, s.integrator, s.dt, {}}, tasks));
  }
  s.clock.restart();
  for (auto& [view, controls] : s.body_controls) controls->reset();  // new worlds
}

render::ViewerContext AppState::viewer_context() const {
  render::ViewerContext c;
  c.runs = run_pointers();
  c.camera_yaw_degrees = camera.yaw_degrees;
  c.scene_name = edited.name;
  c.camera = &camera;
  if (window_width > 0 && window_height > 0)
    c.viewport = frame_viewports(std::max<int>(1, static_cast<int>(runs.size())), window_width,
                                 window_height, frame)
                     .front();
  if (ImGui::GetCurrentContext()) {  // ImGui's mouse is in window units, the viewport in pixels
    const ImGuiIO& io = ImGui::GetIO();
    c.mouse = Eigen::Vector2d(io.MousePos.x * io.DisplayFramebufferScale.x,
                              io.MousePos.y * io.DisplayFramebufferScale.y);
  }
  return c;
}

void add_body_controls(AppState& s) {
  for (const BodyView* view : body_views())
    if (auto controls = render::make_body_controls(*view))
      s.body_controls.emplace_back(view, std::move(controls));
}

std::vector<const BodyView*> shown_views(const AppState& s) {
  if (s.runs.empty() || !s.runs.front()->ok()) return {};
  return views_in(s.runs.front()->simulator()->world());
}

namespace {

BackendOptions window_options(const AppOptions& opt) {
  BackendOptions bo;
  bo.name = opt.backend;
  bo.width = opt.width;
  bo.height = opt.height;
  bo.title = "Jelly Lab";
  bo.vsync = opt.benchmark == 0 && !opt.smoke_test;
  return bo;
}

/// The created backend's window, or null after a message saying why there is none.
WindowBackend* window_of(const BackendResult& created) {
  if (!created.backend) {
    std::cerr << "jelly-lab: " << created.error
              << "\n(no display? use `jelly-lab --headless SCENE --frames DIR`)\n";
    return nullptr;
  }
  auto* window = dynamic_cast<WindowBackend*>(created.backend.get());
  if (!window) {
    std::cerr
        << "jelly-lab: no window could be opened (" << created.backend->name()
        << " backend); use `jelly-lab --headless SCENE --frames DIR` to render without a display\n";
  }
  return window;
}

/// The window's frames until it closes: input, stepping, drawing, recording and the frame rate.
class FrameLoop {
 public:
  FrameLoop(const AppOptions& opt, WindowBackend& window, Renderer& renderer, AppState& s,
            SmokeScript& script)
      : opt_(opt), window_(window), renderer_(renderer), s_(s), script_(script) {}

  /// The exit code.
  int run() {
    while (window_.poll()) frame();
    finish();
    return exit_code_;
  }

 private:
  using clock = std::chrono::steady_clock;

  void close() { glfwSetWindowShouldClose(window_.window(), GLFW_TRUE); }

  /// The wall time since the last frame [s], and the smoothed frame rate.
  double tick() {
    const auto now = clock::now();
    const double wall_dt = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    if (frame_number_++ > 0 && wall_dt > 1e-4)
      fps_ = frame_number_ == 2 ? 1.0 / wall_dt : 0.9 * fps_ + 0.1 / wall_dt;
    return wall_dt;
  }

  void frame() {
    const double wall_dt = tick();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();

    // ---- input (outside ImGui's windows) ----
    if (input_.handle(s_)) close();

    // ---- stepping ----
    if (s_.reset_requested) {
      rebuild_runs(s_);
      s_.reset_requested = false;
    }
    const int w = window_.width(), h = window_.height();
    s_.window_width = w;
    s_.window_height = h;
    if (advance_runs(s_, opt_, script_, wall_dt, frame_number_)) close();
    apply_single_step(s_);
    draw(w, h);
  }

  /// Drawing, recording, screenshots.
  void draw(int w, int h) {
    prepare_view(s_, renderer_, w, h);
    draw_panels(s_, fps_);
    const render::ViewerContext context = s_.viewer_context();
    for (auto& [view, controls] : s_.body_controls) controls->update(context);
    ImGui::Render();
    bench_.start();
    draw_frame(renderer_, s_.run_pointers(), s_.camera, s_.frame, w, h);
    record_frame(s_, window_);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (s_.screenshot_requested && !save_screenshot(s_, opt_.screenshot, window_))
      exit_code_ = cli::kExitFailure;
    window_.present();
    if (opt_.benchmark > 0) {
      bench_.stop();
      if (static_cast<int>(bench_.count()) >= opt_.benchmark + 3) close();
    }
  }

  /// After the last frame: the recording closed, the benchmark and the smoke test's failures.
  void finish() {
    if (s_.recording) finish_recording(s_);
    if (opt_.benchmark > 0) bench_.report(window_, renderer_);
    if (opt_.smoke_test && script_.failures() > 0) {
      std::printf("smoke: %d failure(s)\n", script_.failures());
      exit_code_ = cli::kExitFailure;
    }
  }

  const AppOptions& opt_;
  WindowBackend& window_;
  Renderer& renderer_;
  AppState& s_;
  SmokeScript& script_;
  clock::time_point last_ = clock::now();
  double fps_ = 60.0;
  FrameTimes bench_;
  ViewInput input_;
  int exit_code_ = cli::kExitOk;
  int frame_number_ = 0;
};

}  // namespace

int run_app(const AppOptions& opt) {
  const BackendResult created = create_backend(window_options(opt));
  WindowBackend* window = window_of(created);
  if (!window) return cli::kExitFailure;
  Renderer renderer(window->gl(), opt.samples);
  init_imgui(*window);
  AppState s;
  if (const int code = init_state(s, opt); code != cli::kExitOk) return code;
  SmokeScript script;
  if (opt.smoke_test) script.begin(s);
  const int exit_code = FrameLoop(opt, *window, renderer, s, script).run();
  shutdown_imgui();
  s.runs.clear();  // drawables hold GL objects: free them while the context exists
  return exit_code;
}

}  // namespace jelly::app
