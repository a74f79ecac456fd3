#include "jelly/render/backend.hpp"

#include <algorithm>
#include <cstdlib>

namespace jelly::render {

Image Backend::read_pixels() const {
  const Gl* g = gl();
  if (!g) return {};
  return read_framebuffer(*g, width(), height());
}

Image read_framebuffer(const Gl& gl, int width, int height) {
  Image img;
  img.width = width;
  img.height = height;
  img.rgba.resize(static_cast<std::size_t>(width) * height * 4);
  std::vector<std::uint8_t> bottom_up(img.rgba.size());
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.Finish();
  gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  for (int y = 0; y < height; ++y)
    std::copy_n(&bottom_up[(height - 1 - y) * row], row, &img.rgba[y * row]);
  return img;
}

namespace {

class NullBackend : public Backend {
 public:
  explicit NullBackend(const BackendOptions& o) : w_(o.width), h_(o.height) {}
  std::string_view name() const override { return "null"; }
  const Gl* gl() const override { return nullptr; }
  int width() const override { return w_; }
  int height() const override { return h_; }
  Image read_pixels() const override {
    Image img;
    img.width = w_;
    img.height = h_;
    img.rgba.assign(static_cast<std::size_t>(w_) * h_ * 4, 0);
    return img;
  }

 private:
  int w_, h_;
};

// Windows and macOS always have a desktop to open a window on (GLFW reports it when not);
// elsewhere a window needs an X11 or Wayland display.
bool display_available() {
#if defined(_WIN32) || defined(__APPLE__)
  return true;
#else
  const char* x = std::getenv("DISPLAY");
  const char* wl = std::getenv("WAYLAND_DISPLAY");
  return (x && *x) || (wl && *wl);
#endif
}

}  // namespace

std::unique_ptr<Backend> create_null_backend(const BackendOptions& options) {
  return std::make_unique<NullBackend>(options);
}

std::vector<std::string_view> backend_names() { return {"auto", "window", "offscreen", "null"}; }

BackendResult create_backend(const BackendOptions& options) {
  if (options.width <= 0 || options.height <= 0)
    return {nullptr, "framebuffer size must be positive, got " + std::to_string(options.width) +
                         "×" + std::to_string(options.height)};
  if (options.name == "window") return create_window_backend(options);
  if (options.name == "offscreen") return create_offscreen_backend(options);
  if (options.name == "null") return {create_null_backend(options), ""};
  if (options.name == "auto") {
    std::string why = "no display ($DISPLAY and $WAYLAND_DISPLAY unset)";
    if (display_available()) {
      BackendResult w = create_window_backend(options);
      if (w.backend) return w;
      why = w.error;
    }
    BackendResult o = create_offscreen_backend(options);
    if (!o.backend) o.error = "window: " + why + "; offscreen: " + o.error;
    return o;
  }
  return {nullptr, "unknown render backend '" + options.name +
                       "' (expected auto, window, offscreen or null)"};
}

}  // namespace jelly::render
