// The window backend: a GLFW window with an OpenGL 3.3 core context.
#define GLFW_INCLUDE_NONE  // GL types come from jelly/render/gl.hpp
#include <GLFW/glfw3.h>

#include "jelly/render/window_backend.hpp"

namespace jelly::render {

namespace {
void* glfw_proc(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }
std::string glfw_error() {
  const char* text = nullptr;
  glfwGetError(&text);
  return text ? text : "unknown GLFW error";
}
}  // namespace

WindowBackend::~WindowBackend() {
  if (window_) glfwDestroyWindow(window_);
  glfwTerminate();
}

int WindowBackend::width() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return w;
}

int WindowBackend::height() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return h;
}

bool WindowBackend::poll() {
  glfwPollEvents();
  return !glfwWindowShouldClose(window_);
}

void WindowBackend::present() { glfwSwapBuffers(window_); }

Image WindowBackend::read_pixels() const {
  gl_.ReadBuffer(GL_BACK);
  return read_framebuffer(gl_, width(), height());
}

BackendResult create_window_backend(const BackendOptions& options) {
  if (!glfwInit()) return {nullptr, "window backend: GLFW could not start: " + glfw_error()};
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  std::unique_ptr<WindowBackend> b(new WindowBackend());
  b->window_ =
      glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
  if (!b->window_) return {nullptr, "window backend: no OpenGL 3.3 core window: " + glfw_error()};
  glfwMakeContextCurrent(b->window_);
  glfwSwapInterval(options.vsync ? 1 : 0);
  const std::string missing = b->gl_.load(&glfw_proc);
  if (!missing.empty()) return {nullptr, "window backend: GL functions missing: " + missing};
  return {std::move(b), ""};
}

}  // namespace jelly::render
