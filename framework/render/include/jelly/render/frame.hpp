// One frame of one or more runs: the layout, the worlds, their labels, the printed parameters and
// the instability banners. The window app and the headless renderer both draw through this.
#pragma once

#include <string>
#include <vector>

#include "jelly/render/captions.hpp"
#include "jelly/render/renderer.hpp"
#include "jelly/session/captions.hpp"
#include "jelly/session/simulation_run.hpp"

namespace jelly::render {

struct FrameOptions {
  DrawOptions draw;
  bool caption = true;  ///< print the parameters (bottom-left)
  bool labels = true;   ///< label each viewport with its integrator and cost (comparison mode)
  std::vector<std::string> hints;  ///< lines shown at the top (e.g. "HW.T4 not implemented yet")
  /// Space kept free at the left edge [px] (the app's side panel).
  int left_margin = 0;
};

/// Breaks `text` at spaces so no line is wider than max_width pixels at `scale`.
std::string wrap_text(const std::string& text, int max_width, float scale);

/// Text scale for a frame of this height (2× at 720 p).
float text_scale(int frame_height);

/// Makes sure every run has draw proxies (after a reset).
void ensure_drawables(Renderer& renderer, const std::vector<session::SimulationRun*>& runs);
/// A run's draw proxies (its attachment; null before ensure_drawables or after a reset).
SceneDrawable* drawable_of(const session::SimulationRun& run);

/// Draws `runs` side by side into a width×height frame (begin_frame … end_frame included).
/// The camera is shared so comparison viewports show the same view.
void draw_frame(Renderer& renderer, const std::vector<session::SimulationRun*>& runs,
                const OrbitCamera& camera, const FrameOptions& options, int width, int height);

/// Two to four viewports side by side (1×n; 2×2 for four) filling a w×h frame.
std::vector<Viewport> comparison_layout(int count, int width, int height);

/// Comparison mode's text bands [px], so no text covers a view: a label strip above each view (its
/// integrator, step, cost and own parameters, two lines) and the shared caption's strip below all
/// views (four lines). Both 0 for a single run, whose caption stays printed over its view.
struct FrameBands {
  int label = 0;    ///< height of each view's label strip
  int caption = 0;  ///< height of the caption strip at the bottom of the frame
  float label_scale = 1.0f, caption_scale = 1.0f;  ///< text scales in the strips
};
FrameBands frame_bands(int count, int height, const FrameOptions& options);

/// The viewports draw_frame draws `count` runs' scenes into (below their label strips, above the
/// caption strip in comparison mode).
std::vector<Viewport> frame_viewports(int count, int width, int height,
                                      const FrameOptions& options);
/// The same with captions and labels on.
std::vector<Viewport> frame_viewports(int count, int width, int height, int left_margin);

}  // namespace jelly::render
