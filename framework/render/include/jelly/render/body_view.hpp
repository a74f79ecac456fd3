// A body kind's view module: what the renderer, the viewer and `jelly render` ask a kind for (its
// meshes and draw calls, its share of the scene's bounds, its caption lines, the extra points of
// its replays, its panel, keys and help lines, its live controls). Each kind's module is a folder,
// framework/bodies/<kind>/view/ (a library jelly_<kind>_view defining
// jelly::<kind>_view::body_view()); CMake registers every such folder (framework/render/
// CMakeLists.txt writes the list), and general code walks body_views() without naming a kind.
// A kind with no view module is drawn as its particles and springs.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "jelly/render/camera.hpp"
#include "jelly/render/draw_pass.hpp"
#include "jelly/render/gl.hpp"
#include "jelly/scene_spec.hpp"
#include "jelly/world.hpp"

namespace jelly::session {
class SimulationRun;
}

namespace jelly::render {

/// One kind's draw proxies of one World, built from the core's plain descriptions (house style
/// §3) and updated from the state each frame.
class BodyDrawable {
 public:
  virtual ~BodyDrawable() = default;
  /// CPU side of a frame, also with the null backend: follow the world's current state.
  virtual void update(const World& world, const DrawOptions& options) = 0;
  /// Makes its GPU meshes; `particle_positions` is the buffer of every particle's position (for
  /// marker points: GpuMesh::create_on).
  virtual void create_gpu(const Gl& gl, GLuint particle_positions) = 0;
  virtual void destroy_gpu(const Gl& gl) = 0;
  /// Draws its lit surfaces (after the terrains).
  virtual void draw_surfaces(const SurfacePass& pass, const World& world,
                             const DrawOptions& options) = 0;
  /// Whether it draws marker points with these options (the particle positions are uploaded).
  virtual bool has_markers(const DrawOptions&) const { return false; }
  /// Draws its marker points (after the springs and the particle dots).
  virtual void draw_markers(const PointPass&, const World&, const DrawOptions&) {}
  /// How many of the state's first particles are drawn as dots; −1: all of them.
  virtual long dot_count(const World&) const { return -1; }
  /// Why the body is not (fully) drawn, printed over its view as a run that cannot start is
  /// (e.g. a task that is not implemented); "" when all is well. Read after update().
  virtual std::string message() const { return {}; }
};

/// What a kind's viewer controls act on: every run of the viewer (several in comparison mode;
/// each may have failed to build), the view, and the scene's name (for messages).
struct ViewerContext {
  std::vector<session::SimulationRun*> runs;
  double camera_yaw_degrees = 0.0;
  std::string scene_name;
  /// The camera of the view (null when there is none, e.g. in a test without one).
  const OrbitCamera* camera = nullptr;
  /// Where the first run is drawn [window pixels, x right, y down from the window's top-left];
  /// project through `camera` with its width and height.
  Viewport viewport;
  /// The mouse [window pixels, as the viewport].
  Eigen::Vector2d mouse = Eigen::Vector2d::Zero();
};

/// A kind's live controls in the viewer: its keys, its panel section and the smoke test's check of
/// them. One per kind for the app's life; reset() when the runs are rebuilt.
class BodyControls {
 public:
  virtual ~BodyControls() = default;
  /// New worlds: forget what the keys changed.
  virtual void reset() {}
  /// This frame's keys (ImGui with GLFW key codes), outside ImGui's windows.
  virtual void handle_keys(const ViewerContext&) {}
  /// The contents of its panel section (BodyView::panel_title()).
  virtual void draw_panel(const ViewerContext&) {}
  /// Once a frame, after the keys, the mouse and the panel and before drawing: what they changed
  /// takes effect (e.g. a solve the kind runs when something it shows was moved).
  virtual void update(const ViewerContext&) {}
  /// The left button went down at `mouse` over the view, outside ImGui's windows: true when the
  /// kind takes this drag (then the camera does not orbit, and mouse_drag follows it).
  virtual bool mouse_down(const ViewerContext&) { return false; }
  /// The drag the kind took moved to `mouse` (each frame the button is held).
  virtual void mouse_drag(const ViewerContext&) {}
  /// The button of the drag it took went up.
  virtual void mouse_up(const ViewerContext&) {}
  /// --smoke-test, on a scene of this kind: presses its keys and checks what they did; prints a
  /// line, and each failure; returns the number of failures.
  virtual int smoke_check(const ViewerContext&) { return 0; }
};

/// A kind's view module.
class BodyView {
 public:
  virtual ~BodyView() = default;
  /// The kind's name, as a scene's [body] kind and a manifest's `bodies` say it.
  virtual std::string_view kind() const = 0;
  /// Whether `world` holds bodies of this kind.
  virtual bool present(const World& world) const = 0;
  /// Its draw proxies of `world` (null when present(world) is false).
  virtual std::unique_ptr<BodyDrawable> make_drawable(const World& world) const = 0;
  /// Grows the scene's bounds by what it shows (`grow` takes a point). True when that covers the
  /// state's particles; when no kind does, the renderer frames every particle where it is now.
  virtual bool frame(const World& world, const std::function<void(const Vec3&)>& grow) const = 0;

  /// The caption's line about a scene of this kind ("\n<kind>: n = …\n").
  virtual std::string caption_body(const SceneSpec& scene) const = 0;
  /// What the caption adds after the terrains for a scene of this kind.
  virtual std::string caption_tail(const SceneSpec&) const { return {}; }

  /// Points a replay frame may carry after the state's particles (`jelly render --replay`), what
  /// they are called ("… after them"), and placing them in the world.
  virtual long replay_points(const World&) const { return 0; }
  virtual std::string replay_points_name() const { return {}; }
  virtual void place_replay_points(World&, const Vec3Array& /*x*/, long /*first*/) const {}
  /// Text `jelly render`'s help adds to --replay's description (with its own line breaks).
  virtual std::string_view replay_help() const { return {}; }

  /// The Draw panel's names for the surface and the markers ("" : no marker checkbox), and
  /// whether it lists a spring type.
  virtual std::string_view surface_label() const = 0;
  virtual std::string_view markers_label() const { return {}; }
  virtual bool shows_spring_type(SpringType) const { return true; }
  /// Its panel section: title and id (what --open names), "" for none; its line of the key help.
  virtual std::string_view panel_title() const { return {}; }
  virtual std::string_view panel_id() const { return {}; }
  virtual std::string_view keys_help() const { return {}; }
};

/// Every registered view module, in folder order (written by CMake into the jelly::body_views
/// library, which every program that links the renderer links).
const std::vector<const BodyView*>& body_views();

/// The live controls of `view`'s kind in jelly-lab, null when it has none: a view folder's
/// optional second library jelly_<kind>_view_controls (ImGui and GLFW's key codes) defines
/// jelly::<kind>_view::make_controls(), and CMake writes this function into
/// jelly_body_view_controls, which only jelly-lab links.
std::unique_ptr<BodyControls> make_body_controls(const BodyView& view);

/// The view of the scene's body kind; null when its kind has no view module.
const BodyView* view_of(const SceneSpec& scene);
/// The views whose kinds `world` holds.
std::vector<const BodyView*> views_in(const World& world);

}  // namespace jelly::render
