// The GLFW window backend, exposed for the app (ImGui needs the GLFWwindow).
#pragma once

#include "jelly/render/backend.hpp"

struct GLFWwindow;

namespace jelly::render {

class WindowBackend : public Backend {
 public:
  ~WindowBackend() override;
  std::string_view name() const override { return "window"; }
  const Gl* gl() const override { return &gl_; }
  int width() const override;
  int height() const override;
  bool poll() override;
  void present() override;
  Image read_pixels() const override;
  GLFWwindow* window() const { return window_; }

 private:
  friend BackendResult create_window_backend(const BackendOptions& options);
  WindowBackend() = default;
  GLFWwindow* window_ = nullptr;
  Gl gl_;
};

}  // namespace jelly::render
