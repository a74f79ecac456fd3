#include "jelly/render/draw_pass.hpp"

namespace jelly::render {

namespace {
/// Surfaces are pushed back by this polygon offset (factor and units) so that lines drawn on them
/// (springs) stay visible.
constexpr float kSurfaceOffset = 1.0f;
}  // namespace

void GpuMesh::create(const Gl& gl, bool with_normals, bool with_indices) {
  gl.GenVertexArrays(1, &vao);
  gl.BindVertexArray(vao);
  gl.GenBuffers(1, &positions);
  gl.BindBuffer(GL_ARRAY_BUFFER, positions);
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
  if (with_normals) {
    gl.GenBuffers(1, &normals);
    gl.BindBuffer(GL_ARRAY_BUFFER, normals);
    gl.EnableVertexAttribArray(1);
    gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
  }
  if (with_indices) {
    gl.GenBuffers(1, &indices);
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices);
  }
  gl.BindVertexArray(0);
}

void GpuMesh::create_on(const Gl& gl, GLuint shared_positions) {
  create(gl, false, true);
  // Point this VAO's attribute 0 at the shared buffer instead of its own.
  gl.BindVertexArray(vao);
  gl.DeleteBuffers(1, &positions);
  positions = 0;
  gl.BindBuffer(GL_ARRAY_BUFFER, shared_positions);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
  gl.BindVertexArray(0);
}

void GpuMesh::upload_vertices(const Gl& gl, const std::vector<Eigen::Vector3f>& p,
                              const std::vector<Eigen::Vector3f>* n, GLenum usage) {
  gl.BindBuffer(GL_ARRAY_BUFFER, positions);
  gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(p.size() * sizeof(Eigen::Vector3f)),
                p.data(), usage);
  if (n && normals) {
    gl.BindBuffer(GL_ARRAY_BUFFER, normals);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(n->size() * sizeof(Eigen::Vector3f)),
                  n->data(), usage);
  }
  vertex_count = static_cast<GLsizei>(p.size());
}

void GpuMesh::upload_indices(const Gl& gl, const std::vector<std::uint32_t>& idx) {
  gl.BindVertexArray(vao);
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices);
  gl.BufferData(GL_ELEMENT_ARRAY_BUFFER,
                static_cast<GLsizeiptr>(idx.size() * sizeof(std::uint32_t)), idx.data(),
                GL_STATIC_DRAW);
  gl.BindVertexArray(0);
  index_count = static_cast<GLsizei>(idx.size());
}

void GpuMesh::destroy(const Gl& gl) {
  if (positions) gl.DeleteBuffers(1, &positions);
  if (normals) gl.DeleteBuffers(1, &normals);
  if (indices) gl.DeleteBuffers(1, &indices);
  if (vao) gl.DeleteVertexArrays(1, &vao);
  *this = GpuMesh{};
}

void SurfacePass::set_int(const char* uniform, int value) const {
  gl_.Uniform1i(gl_.GetUniformLocation(program_, uniform), value);
}

void SurfacePass::set_color(const char* uniform, const Eigen::Vector3f& c) const {
  gl_.Uniform3f(gl_.GetUniformLocation(program_, uniform), c.x(), c.y(), c.z());
}

void SurfacePass::set_material(const Material& m) const {
  gl_.Uniform1f(gl_.GetUniformLocation(program_, "u_specular"), m.specular);
  gl_.Uniform1f(gl_.GetUniformLocation(program_, "u_shininess"), m.shininess);
}

void SurfacePass::draw_streamed(const Mesh& mesh, GpuMesh& gpu, bool behind_lines) const {
  if (behind_lines) {
    gl_.Enable(GL_POLYGON_OFFSET_FILL);
    gl_.PolygonOffset(kSurfaceOffset, kSurfaceOffset);
  }
  gpu.upload_vertices(gl_, mesh.positions, &mesh.normals, GL_STREAM_DRAW);
  gl_.BindVertexArray(gpu.vao);
  gl_.DrawElements(GL_TRIANGLES, gpu.index_count, GL_UNSIGNED_INT, nullptr);
  if (behind_lines) gl_.Disable(GL_POLYGON_OFFSET_FILL);
}

void PointPass::draw_points(GpuMesh& gpu, const std::vector<std::uint32_t>& indices, float size,
                            const Eigen::Vector3f& c) const {
  gl_.Enable(GL_PROGRAM_POINT_SIZE);
  gl_.Uniform1i(gl_.GetUniformLocation(program_, "u_round"), 1);
  gl_.Uniform1f(gl_.GetUniformLocation(program_, "u_point_size"), size);
  gl_.Uniform4f(gl_.GetUniformLocation(program_, "u_color"), c.x(), c.y(), c.z(), 1.0f);
  gpu.upload_indices(gl_, indices);
  gl_.BindVertexArray(gpu.vao);
  gl_.DrawElements(GL_POINTS, gpu.index_count, GL_UNSIGNED_INT, nullptr);
  gl_.Disable(GL_PROGRAM_POINT_SIZE);
}

}  // namespace jelly::render
