#include "jelly/render/frame.hpp"

#include <algorithm>
#include <cstdio>

namespace jelly::render {

float text_scale(int h) { return std::clamp(static_cast<float>(h) / 360.0f, 1.0f, 2.0f); }

void ensure_drawables(Renderer& renderer, const std::vector<Run*>& runs) {
  for (Run* r : runs)
    if (r->ok() && !r->drawable()) r->set_drawable(renderer.make_drawable(r->simulator()->world()));
}

std::vector<Viewport> frame_viewports(int count, int width, int height, int left_margin) {
  auto vps = comparison_layout(count, width - left_margin, height);
  for (Viewport& v : vps) v.x += left_margin;
  return vps;
}

void draw_frame(Renderer& renderer, const std::vector<Run*>& runs, const OrbitCamera& camera,
                const FrameOptions& o, int width, int height) {
  ensure_drawables(renderer, runs);
  renderer.begin_frame(width, height);
  const float s = text_scale(height);
  const auto vps = frame_viewports(static_cast<int>(runs.size()), width, height, o.left_margin);
  const int pad = static_cast<int>(8 * s);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    Run& run = *runs[i];
    const Viewport& vp = vps[i];
    if (run.ok()) renderer.draw(*run.drawable(), run.simulator()->world(), camera, o.draw, vp);
    int y = vp.y + pad;
    if (o.labels && runs.size() > 1) {
      renderer.draw_text(run_label(run), vp.x + pad, y, s, {1.0f, 0.95f, 0.75f, 1.0f});
      y += Renderer::text_size("X", s).y() + pad;
    }
    if (!run.ok()) {
      renderer.draw_text("cannot run: " + run.error(), vp.x + pad, y, s, {1.0f, 0.5f, 0.4f, 1.0f});
    } else if (const auto& r = run.simulator()->instability()) {
      char buf[256];
      std::snprintf(buf, sizeof buf,
                    "UNSTABLE: %s stopped at step %ld (t = %.3f s, h = %g s): %s\n"
                    "stable step estimate: h <= %.3g s (recommended %.3g s)",
                    std::string(display_name(r->integrator)).c_str(), r->step, r->time, r->step_size,
                    r->reason.c_str(), r->critical_step, r->recommended_step);
      renderer.draw_text(buf, vp.x + pad, y, s, {1.0f, 0.42f, 0.38f, 1.0f});
    }
    if (i > 0) renderer.draw_rect(vp.x - 1, vp.y, 2, vp.height, {0.05f, 0.05f, 0.07f, 1.0f});
  }
  int y = pad;
  for (const std::string& hint : o.hints) {
    renderer.draw_text(hint, o.left_margin + pad, y + (runs.size() > 1 ? 3 * pad : 0) + 
                       (o.labels && runs.size() > 1 ? Renderer::text_size("X", s).y() : 0),
                       s, {1.0f, 0.85f, 0.3f, 1.0f});
    y += Renderer::text_size(hint, s).y() + pad;
  }
  if (o.caption && !runs.empty()) {
    const std::string text = caption(runs.front()->setup(), runs.front()->time(), runs.size() == 1);
    // Shrink the caption to fit the width left of the panel.
    const int room = width - o.left_margin - 3 * pad;
    const float cs = std::min(s, s * room / std::max(1.0f, float(Renderer::text_size(text, s).x())));
    const Eigen::Vector2i size = Renderer::text_size(text, cs);
    renderer.draw_text(text, o.left_margin + pad, height - size.y() - pad / 2, cs,
                       {0.92f, 0.94f, 1.0f, 1.0f});
  }
  renderer.end_frame();
}

}  // namespace jelly::render
