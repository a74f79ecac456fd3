#include "jelly/render/frame.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace jelly::render {

std::string wrap_text(const std::string& text, int max_width, float scale) {
  std::string out, line, word;
  const auto flush_word = [&]() {
    if (word.empty()) return;
    const std::string candidate = line.empty() ? word : line + " " + word;
    if (!line.empty() && Renderer::text_size(candidate, scale).x() > max_width) {
      out += line + "\n";
      line = word;
    } else {
      line = candidate;
    }
    word.clear();
  };
  for (char c : text) {
    if (c == ' ') {
      flush_word();
    } else if (c == '\n') {
      flush_word();
      out += line + "\n";
      line.clear();
    } else {
      word += c;
    }
  }
  flush_word();
  return out + line;
}

float text_scale(int h) { return std::clamp(static_cast<float>(h) / 360.0f, 1.0f, 2.0f); }

SceneDrawable* drawable_of(const session::SimulationRun& run) {
  return dynamic_cast<SceneDrawable*>(run.attachment());
}

void ensure_drawables(Renderer& renderer, const std::vector<session::SimulationRun*>& runs) {
  for (session::SimulationRun* r : runs)
    if (r->ok() && !drawable_of(*r)) r->attach(renderer.make_drawable(r->simulator()->world()));
}

std::vector<Viewport> comparison_layout(int count, int w, int h) {
  std::vector<Viewport> out;
  count = std::clamp(count, 1, 4);
  const int cols = count == 4 ? 2 : count, rows = count == 4 ? 2 : 1;
  for (int i = 0; i < count; ++i) {
    const int c = i % cols, r = i / cols;
    const int x0 = c * w / cols, x1 = (c + 1) * w / cols;
    const int y0 = r * h / rows, y1 = (r + 1) * h / rows;
    out.push_back({x0, y0, x1 - x0, y1 - y0});
  }
  return out;
}

namespace {
/// Lines of text the bands hold, and the shares of the frame's text scale they use.
constexpr int kLabelLines = 2, kCaptionLines = 4;
constexpr float kLabelShare = 0.75f, kCaptionShare = 0.7f;
/// stb_easy_font's line height [px] at scale 1.
constexpr int kLineHeight = 12;
int pad_of(float scale) { return static_cast<int>(8 * scale); }
}  // namespace

FrameBands frame_bands(int count, int height, const FrameOptions& o) {
  FrameBands b;
  if (count < 2) return b;
  const float s = text_scale(height);
  b.label_scale = std::max(1.0f, kLabelShare * s);
  b.caption_scale = std::max(1.0f, kCaptionShare * s);
  if (o.labels)
    b.label = static_cast<int>(std::ceil(kLabelLines * kLineHeight * b.label_scale)) +
              pad_of(b.label_scale);
  if (o.caption)
    b.caption = static_cast<int>(std::ceil(kCaptionLines * kLineHeight * b.caption_scale)) +
                pad_of(b.caption_scale);
  return b;
}

std::vector<Viewport> frame_viewports(int count, int width, int height, const FrameOptions& o) {
  const FrameBands b = frame_bands(count, height, o);
  auto vps = comparison_layout(count, width - o.left_margin, height - b.caption);
  for (Viewport& v : vps) {
    v.x += o.left_margin;
    v.y += b.label;
    v.height = std::max(1, v.height - b.label);
  }
  return vps;
}

std::vector<Viewport> frame_viewports(int count, int width, int height, int left_margin) {
  FrameOptions o;
  o.left_margin = left_margin;
  return frame_viewports(count, width, height, o);
}

namespace {
/// What the run's body drawables say about what they could not draw (BodyDrawable::message).
std::string body_message(const session::SimulationRun& run) {
  std::string out;
  if (const SceneDrawable* d = drawable_of(run))
    for (const auto& body : d->bodies())
      if (std::string m = body->message(); !m.empty()) out += (out.empty() ? "" : "\n") + m;
  return out;
}
}  // namespace

namespace {
/// What one frame's steps share: where they draw, its size, bands and text scale.
struct FrameContext {
  Renderer& renderer;
  const std::vector<session::SimulationRun*>& runs;
  const FrameOptions& o;
  int width, height;
  float s;           ///< the frame's text scale
  FrameBands bands;  ///< comparison mode's strips
  int pad;           ///< [px] the text's margin at scale s
};

/// Why a run in a label strip stopped or cannot run ("" while it runs).
std::string label_alarm(const session::SimulationRun& run) {
  std::string alarm;
  if (!run.ok()) {
    alarm = "cannot run: " + run.error();
  } else if (const auto& r = run.simulator()->instability()) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "UNSTABLE at t = %.3f s (step %ld); stable h <= %.3g s", r->time,
                  r->step, r->critical_step);
    alarm = buf;
  }
  return alarm;
}

/// The view's own label in its strip above it: the run's label (its own parameters on the second
/// line) and, in red after them, why it stopped; shrunk to the strip's width.
void draw_label_strip(const FrameContext& f, const session::SimulationRun& run,
                      const Viewport& vp) {
  Renderer& renderer = f.renderer;
  const int top = vp.y - f.bands.label;
  renderer.draw_rect(vp.x, top, vp.width, f.bands.label, {0.06f, 0.07f, 0.10f, 1.0f});
  const float ls = f.bands.label_scale;
  const int lpad = pad_of(ls) / 2;
  const std::string label = session::run_label(run);
  const std::size_t nl = label.find('\n');
  const std::string first = label.substr(0, nl);
  const std::string own = nl == std::string::npos ? "" : label.substr(nl + 1) + "   ";
  const std::string alarm = label_alarm(run);
  const int w1 = Renderer::text_size(first, ls).x();
  const int w2 = Renderer::text_size(own + alarm, ls).x();
  const float fit_scale =
      std::min(ls, ls * (vp.width - 2 * lpad) / std::max(1.0f, float(std::max(w1, w2))));
  const Eigen::Vector4f light{1.0f, 0.95f, 0.75f, 1.0f};
  renderer.draw_text(first, vp.x + lpad, top + lpad, fit_scale, light, false);
  const int y2 = top + lpad + static_cast<int>(std::lround(kLineHeight * fit_scale));
  if (!own.empty()) renderer.draw_text(own, vp.x + lpad, y2, fit_scale, light, false);
  if (!alarm.empty())
    renderer.draw_text(alarm, vp.x + lpad + Renderer::text_size(own, fit_scale).x(), y2, fit_scale,
                       {1.0f, 0.45f, 0.40f, 1.0f}, false);
}

/// Text written down a view from its top, each piece wrapped and scaled down to the view's width.
class ViewNotes {
 public:
  ViewNotes(const FrameContext& f, const Viewport& vp) : f_(f), vp_(vp), y_(vp.y + f.pad) {}

  void put(const std::string& raw, const Eigen::Vector4f& color, float shrink = 1.0f) {
    const float s = f_.s;
    const int pad = f_.pad;
    const std::string text = wrap_text(raw, vp_.width - 3 * pad, s * shrink);
    const float ts = std::min(s * shrink, fit(text));
    f_.renderer.draw_text(text, vp_.x + pad, y_, ts, color);
    y_ += Renderer::text_size(text, ts).y() + pad;
  }

 private:
  /// Text scaled down to fit the viewport's width.
  float fit(const std::string& text) const {
    const float s = f_.s;
    const float room = static_cast<float>(vp_.width - 3 * f_.pad);
    return std::min(s, s * room / std::max(1.0f, float(Renderer::text_size(text, s).x())));
  }

  const FrameContext& f_;
  const Viewport& vp_;
  int y_;
};

/// The long instability message written over a single view.
std::string instability_note(const InstabilityReport& r) {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "UNSTABLE: %s stopped at step %ld (t = %.3f s, h = %g s): %s\n"
                "stable step estimate: h <= %.3g s (recommended %.3g s)",
                std::string(display_name(r.integrator)).c_str(), r.step, r.time, r.step_size,
                r.reason.c_str(), r.critical_step, r.recommended_step);
  return buf;
}

/// The hints (first view only) and, outside comparison mode, why the run stopped or cannot run.
void draw_view_notes(const FrameContext& f, std::size_t i, const Viewport& vp) {
  const session::SimulationRun& run = *f.runs[i];
  ViewNotes notes(f, vp);
  if (i == 0)
    for (const std::string& hint : f.o.hints) notes.put(hint, {1.0f, 0.85f, 0.3f, 1.0f});
  if (f.bands.label > 0) {
    // Comparison mode: the label strip said it.
  } else if (!run.ok()) {
    notes.put("cannot run: " + run.error(), {1.0f, 0.5f, 0.4f, 1.0f});
  } else if (const std::string said = body_message(run); !said.empty()) {
    notes.put(said, {1.0f, 0.5f, 0.4f, 1.0f});
  } else if (const auto& r = run.simulator()->instability()) {
    notes.put(instability_note(*r), {1.0f, 0.42f, 0.38f, 1.0f}, f.runs.size() > 1 ? 0.75f : 1.0f);
  }
}

/// View i: its scene, label strip, notes, and the divider left of it.
void draw_view(const FrameContext& f, const OrbitCamera& camera, std::size_t i,
               const Viewport& vp) {
  session::SimulationRun& run = *f.runs[i];
  if (run.ok()) f.renderer.draw(*drawable_of(run), run.simulator()->world(), camera, f.o.draw, vp);
  if (f.bands.label > 0) draw_label_strip(f, run, vp);
  draw_view_notes(f, i, vp);
  if (i > 0)
    f.renderer.draw_rect(vp.x - 1, vp.y - f.bands.label, 2, vp.height + f.bands.label,
                         {0.05f, 0.05f, 0.07f, 1.0f});
}

/// The furthest run's time (a stopped run stays behind).
double furthest_time(const std::vector<session::SimulationRun*>& runs) {
  double t = 0.0;
  for (session::SimulationRun* r : runs) t = std::max(t, r->time());
  return t;
}

/// Comparison mode: the shared parameters in their own strip below every view.
void draw_caption_strip(const FrameContext& f) {
  const FrameOptions& o = f.o;
  const std::string raw = caption(f.runs.front()->setup(), furthest_time(f.runs), false);
  const int top = f.height - f.bands.caption;
  f.renderer.draw_rect(o.left_margin, top, f.width - o.left_margin, f.bands.caption,
                       {0.06f, 0.07f, 0.10f, 1.0f});
  const float cs0 = f.bands.caption_scale;
  const int cpad = pad_of(cs0) / 2;
  const std::string& text = raw;
  // Shrink when a line is wider than the frame (or, from a longer caption, the strip too low).
  const Eigen::Vector2i size0 = Renderer::text_size(text, cs0);
  const float cs =
      std::min({cs0, cs0 * (f.bands.caption - cpad) / std::max(1.0f, float(size0.y())),
                cs0 * (f.width - o.left_margin - 2 * cpad) / std::max(1.0f, float(size0.x()))});
  f.renderer.draw_text(text, o.left_margin + cpad, top + cpad, cs, {0.92f, 0.94f, 1.0f, 1.0f},
                       false);
}

/// A single run's caption, printed over the bottom of its view.
void draw_caption_over(const FrameContext& f) {
  const FrameOptions& o = f.o;
  const float s = f.s;
  const int pad = f.pad;
  const std::string text =
      caption(f.runs.front()->setup(), furthest_time(f.runs), f.runs.size() == 1);
  // Shrink the caption to fit the width left of the panel.
  const int room = f.width - o.left_margin - 3 * pad;
  const float cs = std::min(s, s * room / std::max(1.0f, float(Renderer::text_size(text, s).x())));
  const Eigen::Vector2i size = Renderer::text_size(text, cs);
  f.renderer.draw_text(text, o.left_margin + pad, f.height - size.y() - pad / 2, cs,
                       {0.92f, 0.94f, 1.0f, 1.0f});
}
}  // namespace

void draw_frame(Renderer& renderer, const std::vector<session::SimulationRun*>& runs,
                const OrbitCamera& camera, const FrameOptions& o, int width, int height) {
  ensure_drawables(renderer, runs);
  renderer.begin_frame(width, height);
  const float s = text_scale(height);
  const int count = static_cast<int>(runs.size());
  const FrameContext f{
      renderer, runs, o, width, height, s, frame_bands(count, height, o), static_cast<int>(8 * s)};
  const auto vps = frame_viewports(count, width, height, o);
  for (std::size_t i = 0; i < runs.size(); ++i) draw_view(f, camera, i, vps[i]);
  if (o.caption && f.bands.caption > 0)
    draw_caption_strip(f);
  else if (o.caption && !runs.empty())
    draw_caption_over(f);
  renderer.end_frame();
}

}  // namespace jelly::render
