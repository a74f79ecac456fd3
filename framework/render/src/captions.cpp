#include "jelly/render/captions.hpp"

#include "jelly/body_kind.hpp"
#include "jelly/render/body_view.hpp"
#include "jelly/session/captions.hpp"

namespace jelly::render {

namespace {

using session::format_number;

/// The body's line: its view's, or its kind's when it has no view.
std::string body_line(const SceneSpec& sc, const BodyView* view) {
  if (view) return view->caption_body(sc);
  const BodyKindModule* kind = find_body_kind(sc.body_kind.name);
  return kind ? kind->caption_body(sc) : "\n";
}

}  // namespace

std::string caption(const session::RunSetup& s, double time, bool with_integrator) {
  const SceneSpec& sc = s.scene;
  const BodyView* view = view_of(sc);
  std::string out = sc.name.empty() ? std::string("scene") : sc.name;
  // A kind that plays recorded frames integrates nothing: its integrator and step say nothing.
  const BodyKindModule* kind = find_body_kind(sc.body_kind.name);
  if (with_integrator && !(kind && kind->plays_frames()))
    out += "   " + std::string(display_name(s.integrator)) + "   h = " + session::step_text(s.dt);
  out += "   t = " + format_number("%.3f s", time);
  out += body_line(sc, view);
  const auto springs = [&](const char* name, const SpringSettings& ss) {
    if (ss.enabled)
      out += std::string(name) + " ks " + format_number("%g", ss.ks) + " kd " +
             format_number("%g", ss.kd) + "   ";
  };
  springs("structural", sc.structural);
  springs("shear", sc.shear);
  springs("shear_body", sc.shear_body);
  springs("bending", sc.bending);
  if (!sc.terrains.empty()) {
    out += "\n";
    for (const Terrain& t : sc.terrains) {
      const SurfaceProperties& p = t.surface();
      out += t.name + ": eps " + format_number("%g", p.epsilon) + " kr " +
             format_number("%g", p.restitution) + " kf " + format_number("%g", p.friction) + "   ";
    }
  }
  if (view) out += view->caption_tail(sc);
  if (sc.gravity) out += "g = " + format_number("%g", sc.gravity->y()) + " m/s2";
  return out;
}

}  // namespace jelly::render
