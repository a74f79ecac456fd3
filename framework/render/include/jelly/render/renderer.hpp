// The renderer: draws a World (terrains, jelly or cloth surface, spheres, particles, springs, pins,
// ground grid) and text into a frame. The same code draws into the window and into OSMesa's memory;
// with no GL (the null backend) it still builds and updates every draw proxy but issues no GL call.
#pragma once

#include <array>
#include <memory>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "jelly/render/camera.hpp"
#include "jelly/render/gl.hpp"
#include "jelly/render/meshes.hpp"
#include "jelly/session/simulation_run.hpp"
#include "jelly/world.hpp"

namespace jelly::render {

/// What to draw of a world.
struct DrawOptions {
  bool surface = true;            ///< the jelly's outer faces, the cloth's two sides, shaded
  bool particles = false;         ///< every particle (of a cloth: every cloth particle) as a dot
  std::array<bool, 4> springs{};  ///< per SpringType (structural, shear, shear_body, bending)
  bool pins = true;               ///< cloth scenes: the pinned particles as larger marked dots
  bool grid = true;               ///< grid lines on planes (1 m, stronger every 5 m)
  float point_size = 5.0f;        ///< [px] at 720 p, scaled with the viewport height
};

/// A rectangle of the frame in pixels, origin at the top-left.
struct Viewport {
  int x = 0, y = 0, width = 0, height = 0;
  double aspect() const { return height > 0 ? static_cast<double>(width) / height : 1.0; }
};

/// Colours of the things drawn (linear RGB, 0–1); the tests classify pixels with these.
namespace colors {
inline const Eigen::Vector3f kJelly{0.86f, 0.13f, 0.30f};
inline const Eigen::Vector3f kFloor{0.80f, 0.79f, 0.74f};
inline const Eigen::Vector3f kBowl{0.36f, 0.58f, 0.82f};
inline const Eigen::Vector3f kSphere{0.55f, 0.62f, 0.52f};
inline const Eigen::Vector3f kSkyTop{0.13f, 0.16f, 0.23f};
inline const Eigen::Vector3f kSkyHorizon{0.42f, 0.47f, 0.56f};
inline const Eigen::Vector3f kParticle{0.12f, 0.10f, 0.12f};
/// Cloth scenes (assignment A2): the cloth's front (+y side when flat) and back, its pins, and
/// the spheres (dynamic ones are integrated, kinematic ones follow a schedule or the arrow keys).
inline const Eigen::Vector3f kClothFront{0.80f, 0.62f, 0.20f};
inline const Eigen::Vector3f kClothBack{0.52f, 0.38f, 0.86f};
inline const Eigen::Vector3f kPin{0.95f, 0.12f, 0.10f};
inline const Eigen::Vector3f kDynamicSphere{0.80f, 0.33f, 0.60f};
inline const Eigen::Vector3f kKinematicSphere{0.30f, 0.72f, 0.50f};
/// Per SpringType: structural blue, shear green, body-diagonal shear teal, bending orange.
inline const std::array<Eigen::Vector3f, 4> kSprings{
    Eigen::Vector3f{0.20f, 0.42f, 0.95f}, Eigen::Vector3f{0.15f, 0.75f, 0.30f},
    Eigen::Vector3f{0.10f, 0.70f, 0.75f}, Eigen::Vector3f{0.98f, 0.58f, 0.08f}};
}  // namespace colors

class Renderer;

/// The draw proxies of one World: terrain meshes (static), jelly and cloth surfaces, the spheres
/// of a cloth scene, particles and springs (updated from the state each frame). Make a new one when
/// the world is rebuilt: a run holds it as its attachment, which the run drops when it rebuilds its
/// world.
class SceneDrawable : public session::RunAttachment {
 public:
  ~SceneDrawable() override;
  SceneDrawable(const SceneDrawable&) = delete;
  SceneDrawable& operator=(const SceneDrawable&) = delete;
  const Bounds& bounds() const { return bounds_; }
  const std::vector<JellySurface>& surfaces() const { return surfaces_; }
  const std::vector<Mesh>& terrain_meshes() const { return terrain_meshes_; }
  const std::vector<ClothSurface>& cloth_surfaces() const { return cloth_surfaces_; }
  /// One per World sphere (cloth scenes), in World::sphere() order.
  const std::vector<MovingSphere>& spheres() const { return spheres_; }

 private:
  friend class Renderer;
  struct Gpu;
  SceneDrawable() = default;
  Bounds bounds_;
  std::vector<Mesh> terrain_meshes_;          // one per terrain, in World::terrains() order
  std::vector<JellySurface> surfaces_;        // one per cube
  std::vector<ClothSurface> cloth_surfaces_;  // one per cloth
  std::vector<MovingSphere> spheres_;         // one per sphere of a cloth scene
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
  /// Builds the draw proxies of `world` (its terrains, cubes and springs).
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
  void draw_overlay_triangles(const std::vector<float>& xy, const std::vector<std::uint8_t>& rgba);

  const Gl* gl_;
  std::unique_ptr<Programs> programs_;
  int frame_w_ = 0, frame_h_ = 0;
  int samples_ = 0;
  int wanted_samples_ = 4;
  unsigned fbo_ = 0, color_rb_ = 0, depth_rb_ = 0;
};

}  // namespace jelly::render
