// The pieces of jelly-lab's frame loop, which run_app (app.cpp) puts together in this order each
// frame: input, stepping (or the smoke-test script), drawing, recording and screenshots.
#pragma once

#include <chrono>
#include <ctime>
#include <filesystem>
#include <vector>

#include "app.hpp"
#include "jelly/render/renderer.hpp"

namespace jelly::app {

// ---- set-up (setup.cpp) ----

/// Dear ImGui on the window's GL context (no imgui.ini written); shutdown_imgui() undoes it.
void init_imgui(render::WindowBackend& window);
void shutdown_imgui();
/// Fills a fresh state from the options: the scene list, the task probe, the clock's factor, the
/// draw options, the first scene, integrator and step, the comparison slots with their
/// --slot-set parameters, and the runs. 0, or the exit code after printing why.
int init_state(AppState& state, const AppOptions& options);

// ---- input (input.cpp) ----

/// Keys and mouse outside ImGui's windows: play/pause, step, reset, camera, screenshot, orbit,
/// zoom; and the body kinds' own keys (BodyControls::handle_keys).
class ViewInput {
 public:
  /// Applies this frame's keys and mouse to `state`; true when Esc asked to quit.
  bool handle(AppState& state);

 private:
  bool dragging_ = false;
  double drag_x_ = 0.0, drag_y_ = 0.0;
  /// The body kind's controls that took the drag (BodyControls::mouse_down), null: the camera's.
  render::BodyControls* drag_owner_ = nullptr;
};

// ---- the smoke test (smoke_script.cpp) ----

/// --smoke-test: every integrator for 2 s of simulated time (0.25 s per frame, no wall clock, so
/// reproducible), then every scene for 3 frames (with the keys of the scene's body kind),
/// then the course scene at 1.5 s for the screenshot.
class SmokeScript {
 public:
  /// Starts on the first integrator, comparison off.
  void begin(AppState& state);
  /// One frame of the script. True when it is over (close the window); it then asks for the
  /// screenshot when `screenshot`.
  bool frame(AppState& state, bool screenshot);
  int failures() const { return failures_; }

 private:
  /// In a scene of a body kind with controls: its keys, checked (BodyControls::smoke_check, e.g.
  /// the pins and the drive of a sheet's scene). A failure is counted and printed.
  void check_body_keys(AppState& state);
  std::vector<IntegratorKind> integrators_{kAllIntegrators.begin(), kAllIntegrators.end()};
  std::size_t integrator_ = 0;
  std::size_t scene_ = 0;
  int scene_frames_ = 0;
  bool scenes_phase_ = false;
  int failures_ = 0;
};

// ---- stepping (stepping.cpp) ----

/// Advances the runs for one frame (never in a draw call): the smoke script, --shot-at, the fixed
/// step of a recording, or the real-time clock while playing. True when the window should close.
bool advance_runs(AppState& state, const AppOptions& options, SmokeScript& script, double wall_dt,
                  int frame_number);
/// The N key's single step (it also pauses).
void apply_single_step(AppState& state);

// ---- drawing (drawing.cpp) ----

/// Layout, hints, draw proxies and a requested camera reset, before the panels and the frame.
void prepare_view(AppState& state, render::Renderer& renderer, int width, int height);

/// --benchmark: the time of each frame's drawing (scene + ImGui + swap), wall and CPU.
class FrameTimes {
 public:
  void start();
  void stop();
  std::size_t count() const { return ms_.size(); }
  /// Prints the median and range, leaving out the first 3 frames (shaders, caches).
  void report(const render::WindowBackend& window, const render::Renderer& renderer) const;

 private:
  std::chrono::steady_clock::time_point t0_;
  std::clock_t c0_ = 0;
  std::vector<double> ms_, cpu_ms_;
};

// ---- recording and screenshots (recording.cpp) ----

/// While recording: this frame's scene (without the panels) as the next PNG.
void record_frame(AppState& state, const render::WindowBackend& window);
/// Ends a recording: the message, and the MP4 when ffmpeg is installed.
void finish_recording(AppState& state);
/// Saves the window to `file` (empty: jelly-lab-TIMESTAMP.png) and prints what happened; false
/// when it could not be written.
bool save_screenshot(AppState& state, const std::filesystem::path& file,
                     const render::WindowBackend& window);

}  // namespace jelly::app
