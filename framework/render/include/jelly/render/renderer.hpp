// The renderer: draws a World (terrains, each body through its kind's view module, particles,
// springs, ground grid) and text into a frame. The same code draws into the window and into
// OSMesa's memory; with no GL (the null backend) it still builds and updates every draw proxy but
// issues no GL call.
#pragma once

#include <array>
#include <memory>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "jelly/render/body_view.hpp"
#include "jelly/render/camera.hpp"
#include "jelly/render/draw_pass.hpp"
#include "jelly/render/gl.hpp"
#include "jelly/render/meshes.hpp"
#include "jelly/session/simulation_run.hpp"
#include "jelly/world.hpp"

namespace jelly::render {

/// Colours of the things drawn (linear RGB, 0–1); the tests classify pixels with these. A body's
/// own colours are its view module's.
namespace colors {
inline const Eigen::Vector3f kFloor{0.80f, 0.79f, 0.74f};
inline const Eigen::Vector3f kBowl{0.36f, 0.58f, 0.82f};
inline const Eigen::Vector3f kSphere{0.55f, 0.62f, 0.52f};
inline const Eigen::Vector3f kSkyTop{0.13f, 0.16f, 0.23f};
inline const Eigen::Vector3f kSkyHorizon{0.42f, 0.47f, 0.56f};
inline const Eigen::Vector3f kParticle{0.12f, 0.10f, 0.12f};
/// Per SpringType: structural blue, shear green, body-diagonal shear teal, bending orange.
inline const std::array<Eigen::Vector3f, 4> kSprings{
    Eigen::Vector3f{0.20f, 0.42f, 0.95f}, Eigen::Vector3f{0.15f, 0.75f, 0.30f},
    Eigen::Vector3f{0.10f, 0.70f, 0.75f}, Eigen::Vector3f{0.98f, 0.58f, 0.08f}};
}  // namespace colors

class Renderer;

/// The draw proxies of one World: terrain meshes (static) and each body kind's (BodyDrawable,
/// updated from the state each frame), and the particles and springs. Make a new one when the
/// world is rebuilt: a run holds it as its attachment, which the run drops when it rebuilds its
/// world.
class SceneDrawable : public session::RunAttachment {
 public:
  ~SceneDrawable() override;
  SceneDrawable(const SceneDrawable&) = delete;
  SceneDrawable& operator=(const SceneDrawable&) = delete;
  const Bounds& bounds() const { return bounds_; }
  const std::vector<Mesh>& terrain_meshes() const { return terrain_meshes_; }
  /// One per kind the world holds, in body_views() order.
  const std::vector<std::unique_ptr<BodyDrawable>>& bodies() const { return bodies_; }
  /// The first body drawable of type T (a view module's), null when there is none.
  template <class T>
  const T* body() const {
    for (const auto& b : bodies_)
      if (const auto* t = dynamic_cast<const T*>(b.get())) return t;
    return nullptr;
  }

 private:
  friend class Renderer;
  struct Gpu;
  SceneDrawable() = default;
  Bounds bounds_;
  std::vector<Mesh> terrain_meshes_;  // one per terrain, in World::terrains() order
  std::vector<std::unique_ptr<BodyDrawable>> bodies_;
  std::unique_ptr<Gpu> gpu_;
};

class Renderer {
 public:
  /// `gl` may be null (null backend). The GL context must stay current while the Renderer lives.
  /// `samples`: multisampling of the frame (4 smooths edges; 0 is faster on software GL).
  explicit Renderer(const Gl* gl, int samples = 4);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  bool has_gl() const { return gl_ != nullptr; }
  /// Builds the draw proxies of `world` (its terrains, bodies and springs).
  std::unique_ptr<SceneDrawable> make_drawable(const World& world);

  /// Starts a frame of width×height pixels: binds the multisampled target, draws the sky.
  void begin_frame(int width, int height);
  /// Draws `world` (current state) into viewport `vp` of the frame.
  void draw(SceneDrawable& drawable, const World& world, const OrbitCamera& camera,
            const DrawOptions& options, const Viewport& vp);
  /// Text at (x, y) [px, top-left of the frame], `scale` × the 7-px built-in font, on a dark
  /// translucent panel when `panel`.
  void draw_text(std::string_view text, int x, int y, float scale,
                 const Eigen::Vector4f& color = {1, 1, 1, 1}, bool panel = true);
  /// Size [px] draw_text would cover.
  static Eigen::Vector2i text_size(std::string_view text, float scale);
  /// A filled rectangle [px, top-left], e.g. a banner's background or a viewport divider.
  void draw_rect(int x, int y, int w, int h, const Eigen::Vector4f& color);
  /// Resolves the frame into the backend's framebuffer (draw ImGui after this).
  void end_frame();

  /// Samples of the multisampled target (0 when drawing straight into the framebuffer).
  int samples() const { return samples_; }

 private:
  struct Programs;
  void ensure_target(int width, int height);
  void draw_terrains(SceneDrawable& drawable, const World& world, const SurfacePass& pass);
  void draw_particles(SceneDrawable& drawable, const World& world, const DrawOptions& options,
                      const Viewport& vp, const Eigen::Matrix4f& view_projection);
  void draw_overlay_triangles(const std::vector<float>& xy, const std::vector<std::uint8_t>& rgba);

  const Gl* gl_;
  std::unique_ptr<Programs> programs_;
  int frame_w_ = 0, frame_h_ = 0;
  int samples_ = 0;
  int wanted_samples_ = 4;
  unsigned fbo_ = 0, color_rb_ = 0, depth_rb_ = 0;
};

}  // namespace jelly::render
