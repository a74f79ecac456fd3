// Internal to the skeleton's controls (skeleton_viewer.cpp): an ik scene's part of the Skeleton
// panel, its keys, the target's drag and the smoke test's check (A4, issue 32).
#pragma once

#include <string>
#include <vector>

#include "jelly/render/body_view.hpp"
#include "jelly/skeleton_player.hpp"

namespace jelly::skeleton_view {

/// The share of the figure's size one key press moves the target (hw3-ik: about 0.054 units).
inline constexpr double kTargetStepShare = 0.01;
/// How near the mouse [pixels] must press to a ball's centre to take it.
inline constexpr double kPickRadiusPixels = 24.0;

/// The ik section of the skeleton's controls. Edits go to every run's player (comparison mode);
/// the panel shows the first's.
class IkControls {
 public:
  void reset() { chain_ = 0, dragged_ = -1; }
  /// Arrows move the selected chain's target along the camera's right and up, Page Up / Page
  /// Down away from and toward the eye; Tab selects the next chain.
  void handle_keys(const render::ViewerContext& c, const std::vector<SkeletonPlayer*>& players);
  /// Moves chain `chain_`'s target by `steps` key steps along camera axis `axis` (camera_axis).
  void nudge(const render::ViewerContext& c, const std::vector<SkeletonPlayer*>& players, int axis,
             double steps);
  /// The panel's ik section: per chain its bones, target, Stable/Unstable, updates and error;
  /// limits, step, epsilon, max_iterations, Reset; the plot of the last solve's error.
  void draw_panel(const render::ViewerContext& c, const std::vector<SkeletonPlayer*>& players);
  /// A press on a ball takes the drag; the drag moves it in the plane facing the camera.
  bool mouse_down(const render::ViewerContext& c, SkeletonPlayer& first);
  void mouse_drag(const render::ViewerContext& c, const std::vector<SkeletonPlayer*>& players);
  void mouse_up() { dragged_ = -1; }
  /// --smoke-test: three presses of the Right arrow move the target, the solve moves the
  /// skeleton and shrinks the error, an idle frame does not solve, and a press on the target and
  /// a drag put it under the mouse. Returns the failures.
  int smoke_check(const render::ViewerContext& c, SkeletonPlayer& p);

 private:
  int smoke_drag(const render::ViewerContext& c, SkeletonPlayer& p);
  void chain_section(const std::vector<SkeletonPlayer*>& players, SkeletonPlayer& p, std::size_t c);
  void settings_section(const std::vector<SkeletonPlayer*>& players, SkeletonPlayer& p);
  void error_plot(SkeletonPlayer& p);
  std::size_t chain_ = 0;  // the chain the keys and the plot are about
  int dragged_ = -1;       // the chain whose ball the mouse drags, −1: none
};

}  // namespace jelly::skeleton_view
