// The off-screen backend: an OSMesa OpenGL 3.3 core context rendering into memory.
// libOSMesa is opened with dlopen so that no binary links it together with libGL.
#include <dlfcn.h>

#include "jelly/render/backend.hpp"

namespace jelly::render {

namespace {

// From <GL/osmesa.h> (Mesa), which cannot be included next to <GL/glcorearb.h>.
using OSMesaContext = struct osmesa_context*;
constexpr int OSMESA_RGBA = GL_RGBA;
constexpr int OSMESA_FORMAT = 0x22;
constexpr int OSMESA_DEPTH_BITS = 0x30;
constexpr int OSMESA_PROFILE = 0x33;
constexpr int OSMESA_CORE_PROFILE = 0x34;
constexpr int OSMESA_CONTEXT_MAJOR_VERSION = 0x36;
constexpr int OSMESA_CONTEXT_MINOR_VERSION = 0x37;

using CreateContextAttribs = OSMesaContext (*)(const int*, OSMesaContext);
using MakeCurrent = GLboolean (*)(OSMesaContext, void*, GLenum, GLsizei, GLsizei);
using DestroyContext = void (*)(OSMesaContext);
using GetProcAddress = void* (*)(const char*);

// OSMesaGetProcAddress of the opened library, for Gl::load (which takes a plain function).
GetProcAddress g_osmesa_get_proc = nullptr;
void* osmesa_proc(const char* name) {
  return g_osmesa_get_proc ? g_osmesa_get_proc(name) : nullptr;
}

class OffscreenBackend : public Backend {
 public:
  ~OffscreenBackend() override {
    if (context_ && destroy_) destroy_(context_);
    if (library_) dlclose(library_);
  }
  std::string_view name() const override { return "offscreen"; }
  const Gl* gl() const override { return &gl_; }
  int width() const override { return width_; }
  int height() const override { return height_; }
  void present() override { gl_.Finish(); }

  std::string open(const BackendOptions& o) {
    for (const char* lib : {"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"}) {
      library_ = dlopen(lib, RTLD_NOW | RTLD_LOCAL);
      if (library_) break;
    }
    if (!library_)
      return "cannot open libOSMesa (install the Debian package libosmesa6): " +
             std::string(dlerror());
    auto create =
        reinterpret_cast<CreateContextAttribs>(dlsym(library_, "OSMesaCreateContextAttribs"));
    auto make_current = reinterpret_cast<MakeCurrent>(dlsym(library_, "OSMesaMakeCurrent"));
    destroy_ = reinterpret_cast<DestroyContext>(dlsym(library_, "OSMesaDestroyContext"));
    g_osmesa_get_proc = reinterpret_cast<GetProcAddress>(dlsym(library_, "OSMesaGetProcAddress"));
    if (!create || !make_current || !destroy_ || !g_osmesa_get_proc)
      return "libOSMesa lacks OSMesaCreateContextAttribs (needs Mesa ≥ 12)";
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    context_ = create(attributes, nullptr);
    if (!context_) return "OSMesa could not create an OpenGL 3.3 core context";
    width_ = o.width;
    height_ = o.height;
    buffer_.assign(static_cast<std::size_t>(width_) * height_ * 4, 0);
    if (!make_current(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_))
      return "OSMesaMakeCurrent failed for " + std::to_string(width_) + "×" +
             std::to_string(height_);
    const std::string missing = gl_.load(&osmesa_proc);
    if (!missing.empty()) return "OSMesa lacks GL functions: " + missing;
    return {};
  }

 private:
  void* library_ = nullptr;
  OSMesaContext context_ = nullptr;
  DestroyContext destroy_ = nullptr;
  std::vector<std::uint8_t> buffer_;  // the colour buffer OSMesa renders into
  int width_ = 0, height_ = 0;
  Gl gl_;
};

}  // namespace

BackendResult create_offscreen_backend(const BackendOptions& options) {
  auto b = std::make_unique<OffscreenBackend>();
  std::string error = b->open(options);
  if (!error.empty()) return {nullptr, "offscreen backend: " + error};
  return {std::move(b), ""};
}

}  // namespace jelly::render
