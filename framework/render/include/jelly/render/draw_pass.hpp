// What the renderer hands a body kind's view module (jelly/render/body_view.hpp) to draw with: the
// draw options, GPU meshes, and the two passes a body draws in (lit surfaces; marker points on the
// particle positions). The renderer sets each pass up for a viewport; a module only picks colours
// and materials and issues its meshes, so the kinds share one way of drawing.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "jelly/render/gl.hpp"
#include "jelly/render/meshes.hpp"

namespace jelly::render {

/// What to draw of a world.
struct DrawOptions {
  bool surface = true;            ///< each body's surface (a solid's outer faces, a sheet's sides)
  bool particles = false;         ///< the bodies' particles as dots
  std::array<bool, 4> springs{};  ///< per SpringType (structural, shear, shear_body, bending)
  bool markers = true;      ///< a body's marked particles as larger dots (its kind says which)
  bool grid = true;         ///< grid lines on planes (1 m, stronger every 5 m)
  float point_size = 5.0f;  ///< [px] at 720 p, scaled with the viewport height
};

/// A rectangle of the frame in pixels, origin at the top-left.
struct Viewport {
  int x = 0, y = 0, width = 0, height = 0;
  double aspect() const { return height > 0 ? static_cast<double>(width) / height : 1.0; }
};

/// How a lit surface shines: the Blinn-Phong specular strength and exponent of the lit shader.
struct Material {
  float specular;
  float shininess;
};

/// Vertex array with a position buffer, an optional normal buffer and an optional index buffer.
struct GpuMesh {
  GLuint vao = 0, positions = 0, normals = 0, indices = 0;
  GLsizei index_count = 0;
  GLsizei vertex_count = 0;

  void create(const Gl& gl, bool with_normals, bool with_indices);
  /// An index-only mesh whose positions are another mesh's buffer `positions` (lines and marker
  /// points on the particles).
  void create_on(const Gl& gl, GLuint positions);
  void upload_vertices(const Gl& gl, const std::vector<Eigen::Vector3f>& p,
                       const std::vector<Eigen::Vector3f>* n, GLenum usage);
  void upload_indices(const Gl& gl, const std::vector<std::uint32_t>& idx);
  void destroy(const Gl& gl);
};

/// The lit-surface program, set up by the renderer for one viewport (camera, sky, grid). Not a
/// plane, no hole, no cavity unless a body sets them.
class SurfacePass {
 public:
  SurfacePass(const Gl& gl, GLuint program) : gl_(gl), program_(program) {}
  void set_int(const char* uniform, int value) const;
  void set_color(const char* uniform, const Eigen::Vector3f& color) const;
  void set_material(const Material& material) const;
  /// Uploads `mesh` (it moves: every frame) into `gpu` and draws its triangles; `behind_lines`
  /// pushes it back a little so that lines drawn on it (springs) stay visible.
  void draw_streamed(const Mesh& mesh, GpuMesh& gpu, bool behind_lines) const;

 private:
  const Gl& gl_;
  GLuint program_;
};

/// The flat program after the springs and the particle dots, for a body's marker points. Its
/// meshes are made with GpuMesh::create_on(gl, particle_positions).
class PointPass {
 public:
  PointPass(const Gl& gl, GLuint program, float dot_size)
      : gl_(gl), program_(program), dot_size_(dot_size) {}
  /// [px] the particle dots' size in this viewport (before their minimum).
  float dot_size() const { return dot_size_; }
  /// Draws the particles `indices` as round dots of `size` [px] in `color`.
  void draw_points(GpuMesh& gpu, const std::vector<std::uint32_t>& indices, float size,
                   const Eigen::Vector3f& color) const;

 private:
  const Gl& gl_;
  GLuint program_;
  float dot_size_;
};

}  // namespace jelly::render
