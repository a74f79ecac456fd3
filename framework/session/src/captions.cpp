#include "jelly/session/captions.hpp"

#include <cstdio>

namespace jelly::session {

namespace {
std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
std::string step_text(double h) {
  return h >= 1e-3 ? fmt("%.4g ms", h * 1e3) : fmt("%.4g us", h * 1e6);
}
}  // namespace

std::string caption(const RunSetup& s, double time, bool with_integrator) {
  const SceneSpec& sc = s.scene;
  std::string out = sc.name.empty() ? std::string("scene") : sc.name;
  if (with_integrator)
    out += "   " + std::string(display_name(s.integrator)) + "   h = " + step_text(s.dt);
  out += "   t = " + fmt("%.3f s", time);
  if (sc.body_kind == BodyKind::Cube) {
    out += "\ncube: n = " + std::to_string(sc.cube.n) + ", L = " + fmt("%.3g m", sc.cube.edge) +
           ", m = " + fmt("%.3g kg", sc.cube.mass) + "\n";
  } else if (sc.body_kind == BodyKind::Cloth) {
    const ClothSpec& c = sc.cloth;
    std::string pins;
    for (const std::string& p : c.pin_sets) pins += (pins.empty() ? "" : "+") + p;
    if (!c.pins.empty()) pins += (pins.empty() ? "" : "+") + std::to_string(c.pins.size());
    out += "\ncloth: n = " + std::to_string(c.n) + ", L = " + fmt("%.3g m", c.size) +
           ", m = " + fmt("%.3g kg", c.mass) + ", pins " + (pins.empty() ? "none" : pins) +
           (c.air_drag > 0.0 ? ", k_air " + fmt("%g", c.air_drag) : std::string()) + "\n";
  } else {
    out += "\nparticles: " + std::to_string(sc.particles.positions.cols()) +
           ", m = " + fmt("%.3g kg", sc.particles.mass) + "\n";
  }
  const auto springs = [&](const char* name, const SpringSettings& ss) {
    if (ss.enabled)
      out += std::string(name) + " ks " + fmt("%g", ss.ks) + " kd " + fmt("%g", ss.kd) + "   ";
  };
  springs("structural", sc.structural);
  springs("shear", sc.shear);
  springs("shear_body", sc.shear_body);
  springs("bending", sc.bending);
  if (!sc.terrains.empty()) {
    out += "\n";
    for (const Terrain& t : sc.terrains) {
      const SurfaceProperties& p = t.surface();
      out += t.name + ": eps " + fmt("%g", p.epsilon) + " kr " + fmt("%g", p.restitution) + " kf " +
             fmt("%g", p.friction) + "   ";
    }
  }
  if (sc.body_kind == BodyKind::Cloth) {
    const ClothCollisionSettings& k = sc.collisions;
    std::size_t kinematic = 0;
    for (const SphereSpec& sp : sc.spheres) kinematic += sp.kinematic ? 1 : 0;
    const std::size_t n = sc.spheres.size();
    out += "\n" + std::to_string(n) + (n == 1 ? " sphere (" : " spheres (") +
           std::to_string(kinematic) + " kinematic): e_cloth " + fmt("%g", k.cloth_restitution) +
           " e_sphere " + fmt("%g", k.sphere_restitution) + " eps " + fmt("%g", k.tolerance) +
           " mu " + fmt("%g", k.friction) + " beta " + fmt("%g", k.push_out) + "   ";
  }
  if (sc.gravity) out += "g = " + fmt("%g", sc.gravity->y()) + " m/s2";
  return out;
}

std::string run_label(const SimulationRun& run) {
  const int evals = evaluations_per_step(run.setup().integrator);
  std::string out = std::string(display_name(run.setup().integrator)) +
                    "   h = " + step_text(run.step()) + "   " + std::to_string(evals) +
                    (evals == 1 ? " eval/step" : " evals/step");
  if (run.ms_per_step() > 0.0) out += "   " + fmt("%.3f ms/step", run.ms_per_step());
  if (!run.setup().overrides.empty()) out += "\n" + run.setup().overrides;
  return out;
}

}  // namespace jelly::session
