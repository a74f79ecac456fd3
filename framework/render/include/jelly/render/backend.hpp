// Render backends: where the GL context and the pixels live (house style §4).
//
//   "window"     a GLFW window with an OpenGL 3.3 core context (needs a display)
//   "offscreen"  an OSMesa context rendering into memory (no display; llvmpipe)
//   "null"       no GL at all: the renderer builds its meshes but issues no GL call (tests)
//   "auto"       window when a display is available, else offscreen
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "jelly/render/gl.hpp"
#include "jelly/render/image.hpp"

namespace jelly::render {

struct BackendOptions {
  std::string name = "auto";  ///< auto | window | offscreen | null
  int width = 1280;           ///< framebuffer size [px]
  int height = 720;
  std::string title = "Jelly Lab";
  bool vsync = true;  ///< window only: swap interval 1
};

class Backend {
 public:
  virtual ~Backend() = default;
  /// "window", "offscreen" or "null".
  virtual std::string_view name() const = 0;
  /// The loaded GL functions; nullptr for the null backend.
  virtual const Gl* gl() const = 0;
  /// Framebuffer size in pixels (the window's may change when it is resized).
  virtual int width() const = 0;
  virtual int height() const = 0;
  /// Processes window events. False once the user asked to close the window.
  virtual bool poll() { return true; }
  /// Finishes the frame: swaps buffers (window) or waits for rendering to finish (offscreen).
  virtual void present() {}
  /// The pixels of the frame being drawn. Call after drawing and before present().
  virtual Image read_pixels() const;
};

struct BackendResult {
  std::unique_ptr<Backend> backend;
  std::string error;  ///< why it could not be created (empty on success)
};

/// Creates the named backend. "auto" tries the window when $DISPLAY or $WAYLAND_DISPLAY is set,
/// and the offscreen backend otherwise (or when the window fails).
BackendResult create_backend(const BackendOptions& options);
/// The names create_backend accepts.
std::vector<std::string_view> backend_names();

/// Individual backends (create_backend chooses among these).
BackendResult create_window_backend(const BackendOptions& options);
BackendResult create_offscreen_backend(const BackendOptions& options);
std::unique_ptr<Backend> create_null_backend(const BackendOptions& options);

/// Reads the current draw framebuffer's colour (rows flipped to top-first).
Image read_framebuffer(const Gl& gl, int width, int height);

}  // namespace jelly::render
