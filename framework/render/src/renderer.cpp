#include "jelly/render/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>

#include "shaders.hpp"

// stb_easy_font: a public-domain 7-px bitmap font as quads (Debian libstb-dev, header only).
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#endif
#include <stb_easy_font.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace jelly::render {

namespace {

/// How the terrains shine (a body's material is its view module's).
constexpr Material kGroundMaterial{0.08f, 24.0f};  ///< planes and spheres: nearly matte
constexpr Material kBowlMaterial{0.25f, 40.0f};    ///< the bowl: a glazed dish
/// Opacity of spring lines (the surface and other springs show through a little).
constexpr float kSpringAlpha = 0.85f;
/// Particle dots: `point_size` is in pixels at this viewport height, and never below the minimum.
constexpr float kPointSizeReferenceHeight = 720.0f;
constexpr float kMinPointSize = 2.0f;

GLuint compile(const Gl& gl, GLenum type, const char* source) {
  const GLuint s = gl.CreateShader(type);
  gl.ShaderSource(s, 1, &source, nullptr);
  gl.CompileShader(s);
  GLint ok = 0;
  gl.GetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    gl.GetShaderInfoLog(s, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("shader compile error: ") + log);
  }
  return s;
}

GLuint link(const Gl& gl, const char* vs, const char* fs) {
  const GLuint v = compile(gl, GL_VERTEX_SHADER, vs), f = compile(gl, GL_FRAGMENT_SHADER, fs);
  const GLuint p = gl.CreateProgram();
  gl.AttachShader(p, v);
  gl.AttachShader(p, f);
  gl.LinkProgram(p);
  gl.DeleteShader(v);
  gl.DeleteShader(f);
  GLint ok = 0;
  gl.GetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    gl.GetProgramInfoLog(p, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("shader link error: ") + log);
  }
  return p;
}

}  // namespace

// ------------------------------------------------------------------------------------------------
struct SceneDrawable::Gpu {
  const Gl* gl = nullptr;
  SceneDrawable* owner = nullptr;
  std::vector<GpuMesh> terrains;
  GpuMesh particles;                  // positions of every particle (points)
  std::vector<GpuMesh> spring_lines;  // per spring group: particle positions + pair indices
  std::vector<SpringType> spring_types;
  std::vector<Eigen::Vector3f> scratch;
  ~Gpu() {
    for (auto& m : terrains) m.destroy(*gl);
    for (auto& b : owner->bodies_) b->destroy_gpu(*gl);
    particles.destroy(*gl);
    for (auto& m : spring_lines) m.destroy(*gl);
  }
};

SceneDrawable::~SceneDrawable() = default;

struct Renderer::Programs {
  GLuint surface = 0, flat = 0, sky = 0, overlay = 0;
  GLuint empty_vao = 0;
  GLuint overlay_vao = 0, overlay_xy = 0, overlay_rgba = 0;
};

Renderer::Renderer(const Gl* gl, int samples) : gl_(gl), wanted_samples_(samples) {
  if (!gl_) return;
  const Gl& g = *gl_;
  programs_ = std::make_unique<Programs>();
  programs_->surface = link(g, shaders::kSurfaceVertex, shaders::kSurfaceFragment);
  programs_->flat = link(g, shaders::kFlatVertex, shaders::kFlatFragment);
  programs_->sky = link(g, shaders::kSkyVertex, shaders::kSkyFragment);
  programs_->overlay = link(g, shaders::kOverlayVertex, shaders::kOverlayFragment);
  g.GenVertexArrays(1, &programs_->empty_vao);
  g.GenVertexArrays(1, &programs_->overlay_vao);
  g.BindVertexArray(programs_->overlay_vao);
  g.GenBuffers(1, &programs_->overlay_xy);
  g.BindBuffer(GL_ARRAY_BUFFER, programs_->overlay_xy);
  g.EnableVertexAttribArray(0);
  g.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
  g.GenBuffers(1, &programs_->overlay_rgba);
  g.BindBuffer(GL_ARRAY_BUFFER, programs_->overlay_rgba);
  g.EnableVertexAttribArray(1);
  g.VertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, 4, nullptr);
  g.BindVertexArray(0);
}

Renderer::~Renderer() {
  if (!gl_) return;
  const Gl& g = *gl_;
  g.DeleteProgram(programs_->surface);
  g.DeleteProgram(programs_->flat);
  g.DeleteProgram(programs_->sky);
  g.DeleteProgram(programs_->overlay);
  g.DeleteVertexArrays(1, &programs_->empty_vao);
  g.DeleteVertexArrays(1, &programs_->overlay_vao);
  g.DeleteBuffers(1, &programs_->overlay_xy);
  g.DeleteBuffers(1, &programs_->overlay_rgba);
  if (fbo_) g.DeleteFramebuffers(1, &fbo_);
  if (color_rb_) g.DeleteRenderbuffers(1, &color_rb_);
  if (depth_rb_) g.DeleteRenderbuffers(1, &depth_rb_);
}

std::unique_ptr<SceneDrawable> Renderer::make_drawable(const World& world) {
  std::unique_ptr<SceneDrawable> d(new SceneDrawable());
  d->bounds_ = scene_bounds(world);
  const double half = plane_half_extent(d->bounds_);
  for (const Terrain& t : world.terrains()) {
    if (const auto* p = std::get_if<Plane>(&t.shape))
      d->terrain_meshes_.push_back(plane_mesh(*p, d->bounds_.center(), half));
    else if (const auto* b = std::get_if<Bowl>(&t.shape))
      d->terrain_meshes_.push_back(bowl_mesh(*b));
    else
      d->terrain_meshes_.push_back(sphere_mesh(std::get<Sphere>(t.shape)));
  }
  for (const BodyView* view : body_views())
    if (view->present(world)) d->bodies_.push_back(view->make_drawable(world));
  if (!gl_) return d;

  const Gl& g = *gl_;
  d->gpu_ = std::make_unique<SceneDrawable::Gpu>();
  d->gpu_->gl = gl_;
  d->gpu_->owner = d.get();
  for (const Mesh& m : d->terrain_meshes_) {
    GpuMesh gm;
    gm.create(g, true, true);
    gm.upload_vertices(g, m.positions, &m.normals, GL_STATIC_DRAW);
    gm.upload_indices(g, m.indices);
    d->gpu_->terrains.push_back(gm);
  }
  d->gpu_->particles.create(g, false, false);
  for (auto& body : d->bodies_) body->create_gpu(g, d->gpu_->particles.positions);
  for (const SpringGroup& group : world.spring_groups()) {
    GpuMesh gm;
    // Lines read the particle positions buffer.
    gm.create_on(g, d->gpu_->particles.positions);
    std::vector<std::uint32_t> idx;
    idx.reserve(group.springs.size() * 2);
    for (const Spring& s : group.springs)
      idx.insert(idx.end(), {std::uint32_t(s.a), std::uint32_t(s.b)});
    gm.upload_indices(g, idx);
    d->gpu_->spring_lines.push_back(gm);
    d->gpu_->spring_types.push_back(group.type);
  }
  return d;
}

void Renderer::ensure_target(int w, int h) {
  const Gl& g = *gl_;
  if (w == frame_w_ && h == frame_h_ && (fbo_ || samples_ == 0)) return;
  frame_w_ = w;
  frame_h_ = h;
  if (fbo_) g.DeleteFramebuffers(1, &fbo_);
  if (color_rb_) g.DeleteRenderbuffers(1, &color_rb_);
  if (depth_rb_) g.DeleteRenderbuffers(1, &depth_rb_);
  fbo_ = color_rb_ = depth_rb_ = 0;
  GLint max_samples = 0;
  g.GetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples_ = std::min(wanted_samples_, static_cast<int>(max_samples));
  if (samples_ < 2) {
    samples_ = 0;
    return;
  }
  g.GenFramebuffers(1, &fbo_);
  g.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
  g.GenRenderbuffers(1, &color_rb_);
  g.BindRenderbuffer(GL_RENDERBUFFER, color_rb_);
  g.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, w, h);
  g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_rb_);
  g.GenRenderbuffers(1, &depth_rb_);
  g.BindRenderbuffer(GL_RENDERBUFFER, depth_rb_);
  g.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT24, w, h);
  g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb_);
  if (g.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    g.BindFramebuffer(GL_FRAMEBUFFER, 0);
    g.DeleteFramebuffers(1, &fbo_);
    fbo_ = 0;
    samples_ = 0;
  }
}

void Renderer::begin_frame(int width, int height) {
  if (!gl_) return;
  const Gl& g = *gl_;
  ensure_target(width, height);
  frame_w_ = width;
  frame_h_ = height;
  g.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
  g.Viewport(0, 0, width, height);
  g.Disable(GL_SCISSOR_TEST);
  g.DepthMask(GL_TRUE);
  g.ClearColor(colors::kSkyHorizon.x(), colors::kSkyHorizon.y(), colors::kSkyHorizon.z(), 1.0f);
  g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  g.Disable(GL_DEPTH_TEST);
  g.UseProgram(programs_->sky);
  g.Uniform3f(g.GetUniformLocation(programs_->sky, "u_top"), colors::kSkyTop.x(),
              colors::kSkyTop.y(), colors::kSkyTop.z());
  g.Uniform3f(g.GetUniformLocation(programs_->sky, "u_horizon"), colors::kSkyHorizon.x(),
              colors::kSkyHorizon.y(), colors::kSkyHorizon.z());
  g.BindVertexArray(programs_->empty_vao);
  g.DrawArrays(GL_TRIANGLES, 0, 3);
  g.BindVertexArray(0);
}

void Renderer::draw(SceneDrawable& d, const World& world, const OrbitCamera& cam,
                    const DrawOptions& opt, const Viewport& vp) {
  // CPU side first (also with the null backend): follow the particles.
  for (auto& body : d.bodies_) body->update(world, opt);
  if (!gl_ || !d.gpu_) return;
  const Gl& g = *gl_;

  g.Viewport(vp.x, frame_h_ - vp.y - vp.height, vp.width, vp.height);
  g.Enable(GL_SCISSOR_TEST);
  g.Scissor(vp.x, frame_h_ - vp.y - vp.height, vp.width, vp.height);
  g.Clear(GL_DEPTH_BUFFER_BIT);
  g.Enable(GL_DEPTH_TEST);
  g.DepthFunc(GL_LEQUAL);

  const Eigen::Matrix4f vpm = cam.projection(vp.aspect()) * cam.view();
  const Vec3 eye = cam.eye();
  const GLuint sp = programs_->surface;
  const SurfacePass pass(g, sp);
  g.UseProgram(sp);
  g.UniformMatrix4fv(g.GetUniformLocation(sp, "u_view_projection"), 1, GL_FALSE, vpm.data());
  pass.set_color("u_eye", eye.cast<float>());
  pass.set_color("u_sky", colors::kSkyHorizon);
  pass.set_int("u_grid", opt.grid ? 1 : 0);
  draw_terrains(d, world, pass);

  // The bodies' surfaces (each kind's view module), then the particles, springs and markers.
  g.Uniform2f(g.GetUniformLocation(sp, "u_cavity"), 0.0f, 0.0f);
  for (auto& body : d.bodies_) body->draw_surfaces(pass, world, opt);
  draw_particles(d, world, opt, vp, vpm);
  g.BindVertexArray(0);
  g.Disable(GL_SCISSOR_TEST);
  g.Disable(GL_DEPTH_TEST);
  g.Viewport(0, 0, frame_w_, frame_h_);
}

void Renderer::draw_terrains(SceneDrawable& d, const World& world, const SurfacePass& pass) {
  const Gl& g = *gl_;
  const GLuint sp = programs_->surface;
  const auto& terrains = world.terrains();
  for (std::size_t i = 0; i < terrains.size() && i < d.gpu_->terrains.size(); ++i) {
    const Terrain& t = terrains[i];
    pass.set_int("u_plane", 0);
    pass.set_int("u_has_hole", 0);
    pass.set_material(kGroundMaterial);
    g.Uniform2f(g.GetUniformLocation(sp, "u_cavity"), 0.0f, 0.0f);
    if (const auto* p = std::get_if<Plane>(&t.shape)) {
      Vec3 u, w;
      const Vec3 n = p->normal.normalized();
      plane_basis(n, u, w);
      pass.set_int("u_plane", 1);
      pass.set_color("u_color", colors::kFloor);
      pass.set_color("u_axis_u", u.cast<float>());
      pass.set_color("u_axis_w", w.cast<float>());
      pass.set_color("u_plane_normal", n.cast<float>());
      pass.set_int("u_has_hole", p->has_hole ? 1 : 0);
      pass.set_color("u_hole_center", p->hole_center.cast<float>());
      g.Uniform1f(g.GetUniformLocation(sp, "u_hole_radius"), static_cast<float>(p->hole_radius));
      const Vec3 centre = p->has_hole ? p->hole_center : d.bounds_.center();
      pass.set_color("u_fade_center", centre.cast<float>());
      g.Uniform1f(g.GetUniformLocation(sp, "u_fade_radius"),
                  static_cast<float>(plane_half_extent(d.bounds_)));
    } else if (const auto* b = std::get_if<Bowl>(&t.shape)) {
      pass.set_color("u_color", colors::kBowl);
      g.Uniform2f(g.GetUniformLocation(sp, "u_cavity"),
                  static_cast<float>(b->center.y() - b->radius), static_cast<float>(b->rim_height));
      pass.set_material(kBowlMaterial);
    } else {
      pass.set_color("u_color", colors::kSphere);
    }
    g.BindVertexArray(d.gpu_->terrains[i].vao);
    g.DrawElements(GL_TRIANGLES, d.gpu_->terrains[i].index_count, GL_UNSIGNED_INT, nullptr);
  }
}

void Renderer::draw_particles(SceneDrawable& d, const World& world, const DrawOptions& opt,
                              const Viewport& vp, const Eigen::Matrix4f& vpm) {
  // Particles, springs and the bodies' markers share one position buffer.
  const Gl& g = *gl_;
  SceneDrawable::Gpu& gpu = *d.gpu_;
  const bool any_springs =
      std::any_of(opt.springs.begin(), opt.springs.end(), [](bool b) { return b; });
  const bool markers = std::any_of(d.bodies_.begin(), d.bodies_.end(),
                                   [&](const auto& b) { return b->has_markers(opt); });
  if (!opt.particles && !any_springs && !markers) return;
  const Vec3Array& x = world.state().x;
  gpu.scratch.resize(static_cast<std::size_t>(x.cols()));
  for (Eigen::Index i = 0; i < x.cols(); ++i) gpu.scratch[i] = x.col(i).cast<float>();
  gpu.particles.upload_vertices(g, gpu.scratch, nullptr, GL_STREAM_DRAW);
  const GLuint fp = programs_->flat;
  const auto loc = [&](const char* name) { return g.GetUniformLocation(fp, name); };
  g.UseProgram(fp);
  g.UniformMatrix4fv(loc("u_view_projection"), 1, GL_FALSE, vpm.data());
  g.Uniform1i(loc("u_round"), 0);
  g.Enable(GL_BLEND);
  g.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (std::size_t i = 0; i < gpu.spring_lines.size(); ++i) {
    const auto type = static_cast<std::size_t>(gpu.spring_types[i]);
    if (!opt.springs[type]) continue;
    const Eigen::Vector3f& c = colors::kSprings[type];
    g.Uniform4f(loc("u_color"), c.x(), c.y(), c.z(), kSpringAlpha);
    g.BindVertexArray(gpu.spring_lines[i].vao);
    g.DrawElements(GL_LINES, gpu.spring_lines[i].index_count, GL_UNSIGNED_INT, nullptr);
  }
  g.Disable(GL_BLEND);
  if (opt.particles) {
    g.Enable(GL_PROGRAM_POINT_SIZE);
    g.Uniform1i(loc("u_round"), 1);
    g.Uniform1f(loc("u_point_size"),
                std::max(kMinPointSize, opt.point_size * vp.height / kPointSizeReferenceHeight));
    const Eigen::Vector3f& c = colors::kParticle;
    g.Uniform4f(loc("u_color"), c.x(), c.y(), c.z(), 1.0f);
    g.BindVertexArray(gpu.particles.vao);
    // A body kind may draw only some of the state's particles as dots (its first ones).
    GLsizei count = gpu.particles.vertex_count;
    for (const auto& body : d.bodies_)
      if (const long n = body->dot_count(world); n >= 0) {
        count = static_cast<GLsizei>(n);
        break;
      }
    g.DrawArrays(GL_POINTS, 0, count);
    g.Disable(GL_PROGRAM_POINT_SIZE);
  }
  const PointPass points(g, fp, opt.point_size * vp.height / kPointSizeReferenceHeight);
  for (auto& body : d.bodies_)
    if (body->has_markers(opt)) body->draw_markers(points, world, opt);
}

Eigen::Vector2i Renderer::text_size(std::string_view text, float scale) {
  std::string s(text);
  // stb_easy_font_height counts 12 px per line; the glyphs themselves are 7 px tall.
  return {static_cast<int>(std::ceil(stb_easy_font_width(s.data()) * scale)),
          static_cast<int>(std::ceil(stb_easy_font_height(s.data()) * scale))};
}

void Renderer::draw_overlay_triangles(const std::vector<float>& xy,
                                      const std::vector<std::uint8_t>& rgba) {
  if (!gl_ || xy.empty()) return;
  const Gl& g = *gl_;
  g.Disable(GL_DEPTH_TEST);
  g.Enable(GL_BLEND);
  g.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  g.UseProgram(programs_->overlay);
  g.Uniform2f(g.GetUniformLocation(programs_->overlay, "u_frame"), static_cast<float>(frame_w_),
              static_cast<float>(frame_h_));
  g.BindVertexArray(programs_->overlay_vao);
  g.BindBuffer(GL_ARRAY_BUFFER, programs_->overlay_xy);
  g.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(xy.size() * sizeof(float)), xy.data(),
               GL_STREAM_DRAW);
  g.BindBuffer(GL_ARRAY_BUFFER, programs_->overlay_rgba);
  g.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(rgba.size()), rgba.data(), GL_STREAM_DRAW);
  g.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(xy.size() / 2));
  g.BindVertexArray(0);
  g.Disable(GL_BLEND);
}

namespace {
void push_rect(std::vector<float>& xy, std::vector<std::uint8_t>& rgba, float x0, float y0,
               float x1, float y1, const std::uint8_t c[4]) {
  const float v[12] = {x0, y0, x1, y0, x1, y1, x0, y0, x1, y1, x0, y1};
  xy.insert(xy.end(), v, v + 12);
  for (int i = 0; i < 6; ++i) rgba.insert(rgba.end(), c, c + 4);
}
std::uint8_t to_byte(float f) {
  return static_cast<std::uint8_t>(std::clamp(f, 0.0f, 1.0f) * 255.0f + 0.5f);
}
}  // namespace

void Renderer::draw_rect(int x, int y, int w, int h, const Eigen::Vector4f& color) {
  std::vector<float> xy;
  std::vector<std::uint8_t> rgba;
  const std::uint8_t c[4] = {to_byte(color[0]), to_byte(color[1]), to_byte(color[2]),
                             to_byte(color[3])};
  push_rect(xy, rgba, float(x), float(y), float(x + w), float(y + h), c);
  draw_overlay_triangles(xy, rgba);
}

void Renderer::draw_text(std::string_view text, int x, int y, float scale,
                         const Eigen::Vector4f& color, bool panel) {
  if (!gl_ || text.empty()) return;
  std::string s(text);
  std::vector<float> xy;
  std::vector<std::uint8_t> rgba;
  const int pad = static_cast<int>(std::ceil(4 * scale));
  if (panel) {
    const Eigen::Vector2i size = text_size(text, scale);
    const std::uint8_t bg[4] = {10, 12, 18, 170};
    push_rect(xy, rgba, float(x - pad), float(y - pad), float(x + size.x() + pad),
              float(y + size.y() - 3 * scale + pad), bg);
  }
  std::vector<char> quads(s.size() * 300 + 1024);  // stb_easy_font: ≤ ~270 bytes per glyph
  const int count = stb_easy_font_print(0.0f, 0.0f, s.data(), nullptr, quads.data(),
                                        static_cast<int>(quads.size()));
  const std::uint8_t c[4] = {to_byte(color[0]), to_byte(color[1]), to_byte(color[2]),
                             to_byte(color[3])};
  for (int q = 0; q < count; ++q) {
    const float* v = reinterpret_cast<const float*>(quads.data() + q * 64);  // 4 × (x, y, z, rgba)
    const float x0 = x + v[0] * scale, y0 = y + v[1] * scale;
    const float x1 = x + v[8] * scale, y1 = y + v[9] * scale;
    push_rect(xy, rgba, x0, y0, x1, y1, c);
  }
  draw_overlay_triangles(xy, rgba);
}

void Renderer::end_frame() {
  if (!gl_) return;
  const Gl& g = *gl_;
  if (fbo_) {
    g.BindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    g.BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    g.BlitFramebuffer(0, 0, frame_w_, frame_h_, 0, 0, frame_w_, frame_h_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
  }
  g.BindFramebuffer(GL_FRAMEBUFFER, 0);
  g.UseProgram(0);
}

}  // namespace jelly::render
