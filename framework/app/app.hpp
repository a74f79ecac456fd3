// The windowed app: owns the window backend, the renderer, ImGui, the runs and the camera.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "jelly/render/body_view.hpp"
#include "jelly/render/camera.hpp"
#include "jelly/render/frame.hpp"
#include "jelly/render/window_backend.hpp"
#include "jelly/session/assignments.hpp"
#include "jelly/session/real_time_clock.hpp"
#include "jelly/session/scene_catalog.hpp"
#include "jelly/session/simulation_run.hpp"
#include "jelly/task_probe.hpp"

namespace jelly::app {

struct AppOptions {
  /// Name under the scenes folder, or a path; empty: the linked assignment's default scene
  /// (session::default_scene_name()).
  std::string scene;
  std::filesystem::path scenes_dir;  ///< empty: session::default_scenes_dir()
  std::string integrator;            ///< empty: the scene's
  double dt = 0.0;                   ///< 0: the scene's
  std::vector<std::string> compare;  ///< 2–4 integrators: start in comparison mode
  std::vector<std::pair<int, std::string>> slot_sets;  ///< --slot-set K:key=value (1-based slot)
  std::string backend = "window";  ///< window | auto (auto falls back to offscreen)
  int width = 1600, height = 900;
  bool smoke_test = false;                  ///< scripted run: every integrator 2 s, every scene
  std::filesystem::path screenshot;         ///< save the last frame here (smoke test, --shot-at)
  double shot_at = -1.0;                    ///< run to this simulated time, screenshot, exit
  int benchmark = 0;                        ///< draw N frames of the first state, print fps
  bool particles = false, springs = false;  ///< initial draw options
  double factor = 1.0;                      ///< real-time factor
  int samples = 4;                          ///< multisampling (0 is faster on software GL)
  std::vector<std::string> open_panels;     ///< panel headers to open at start ("parameters", ...)
};

/// Reads the command line into `options` (options.cpp). nullopt: go on; else the exit code to
/// return (the help or the error was printed).
std::optional<int> parse_options(int argc, char** argv, AppOptions& options);
/// Runs the app; returns the process exit code.
int run_app(const AppOptions& options);

/// One slot of comparison mode.
struct CompareSlot {
  IntegratorKind integrator = IntegratorKind::ExplicitEuler;
  double dt = 0.001;
  std::string overrides;  ///< this run's own parameters, "key=value; …" (session::apply_overrides)
  std::string error;      ///< why the overrides were not applied (shown under the field)
};

/// Everything the panels edit and the loop reads (one owner, passed explicitly).
struct AppState {
  // scenes
  std::filesystem::path scenes_dir;
  std::vector<session::SceneEntry> scenes;
  int scene_index = -1;
  std::string open_path;         ///< the "open a file" text field
  std::string scene_error;       ///< last load or --set error, shown in the panel
  bool scene_not_shown = false;  ///< the last load was a scene this program cannot show (no
                                 ///< linked assignment simulates its kind)
  SceneSpec original;            ///< as loaded (the "reset to the scene's values" target)
  SceneSpec edited;              ///< with the panel's changes
  // simulation
  IntegratorKind integrator = IntegratorKind::ExplicitEuler;
  double dt = 0.001;
  bool playing = true;
  bool step_requested = false;
  bool reset_requested = false;
  session::RealTimeClock clock;
  std::vector<std::unique_ptr<session::SimulationRun>> runs;
  // the body kinds' live controls (keys, panel section), one per registered view that has them
  std::vector<std::pair<const render::BodyView*, std::unique_ptr<render::BodyControls>>>
      body_controls;
  // comparison
  bool comparing = false;
  std::vector<CompareSlot> slots;
  // view
  render::OrbitCamera camera;
  bool camera_reset_requested = true;
  render::FrameOptions frame;
  // student hints
  std::vector<TaskStatus> tasks;
  // recording
  bool recording = false;
  std::filesystem::path record_dir;
  int record_frame = 0;
  std::string record_message;
  bool screenshot_requested = false;
  std::string screenshot_message;
  int panel_width = 400;
  int window_width = 0, window_height = 0;  ///< the last frame's [pixels]
  std::vector<std::string> open_panels;     ///< headers to open on the first frame
  bool scripted = false;  ///< --smoke-test / --shot-at: time is not driven by the clock

  std::vector<session::SimulationRun*> run_pointers() const;
  /// What the body kinds' controls act on: the runs, the camera's yaw, the scene's name, the
  /// camera, the first run's viewport and the mouse.
  render::ViewerContext viewer_context() const;
};

/// Loads scene `index` of state.scenes (or the path in open_path when index < 0) into the state.
bool load_scene_into(AppState& state, int index, const std::string& path = {});
/// Rebuilds the runs from the edited scene, integrator, step and comparison slots (t = 0).
void rebuild_runs(AppState& state);
/// Starts or stops recording PNG frames (and an MP4 when ffmpeg is installed).
void toggle_recording(AppState& state);
/// Makes the controls of every registered body kind that has some (state.body_controls).
void add_body_controls(AppState& state);
/// The registered views whose kinds the shown world (the first run's) holds.
std::vector<const render::BodyView*> shown_views(const AppState& state);

/// Draws the ImGui side panel.
void draw_panels(AppState& state, double fps);

}  // namespace jelly::app
