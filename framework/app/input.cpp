// jelly-lab's keys and mouse outside ImGui's windows.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "app_loop.hpp"

namespace jelly::app {

bool ViewInput::handle(AppState& s) {
  const ImGuiIO& io = ImGui::GetIO();
  bool quit = false;
  if (!io.WantCaptureKeyboard) {
    if (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false)) s.playing = !s.playing;
    if (ImGui::IsKeyPressed(GLFW_KEY_N)) s.step_requested = true;
    if (ImGui::IsKeyPressed(GLFW_KEY_R, false)) s.reset_requested = true;
    if (ImGui::IsKeyPressed(GLFW_KEY_C, false)) s.camera_reset_requested = true;
    if (ImGui::IsKeyPressed(GLFW_KEY_P, false)) s.screenshot_requested = true;
    if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) quit = true;
    // Cloth scenes: 1–4 pin and unpin the corners, the arrows drive the kinematic sphere, S stops
    // it (Space stays play/pause). Ignored in scenes without a cloth or such a sphere.
    static constexpr int kPinKeys[4] = {GLFW_KEY_1, GLFW_KEY_2, GLFW_KEY_3, GLFW_KEY_4};
    for (int corner = 0; corner < 4; ++corner)
      if (ImGui::IsKeyPressed(kPinKeys[corner], false)) toggle_pin(s, corner);
    if (ImGui::IsKeyPressed(GLFW_KEY_LEFT, false)) press_arrow(s, session::Arrow::Left);
    if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT, false)) press_arrow(s, session::Arrow::Right);
    if (ImGui::IsKeyPressed(GLFW_KEY_UP, false)) press_arrow(s, session::Arrow::Up);
    if (ImGui::IsKeyPressed(GLFW_KEY_DOWN, false)) press_arrow(s, session::Arrow::Down);
    if (ImGui::IsKeyPressed(GLFW_KEY_S, false)) stop_sphere(s);
  }
  if (!io.WantCaptureMouse) {
    if (ImGui::IsMouseClicked(0)) {
      dragging_ = true;
      drag_x_ = io.MousePos.x;
      drag_y_ = io.MousePos.y;
    }
    if (io.MouseWheel != 0.0f) s.camera.zoom(io.MouseWheel);
  }
  if (!ImGui::IsMouseDown(0)) dragging_ = false;
  if (dragging_) {
    s.camera.orbit(io.MousePos.x - drag_x_, io.MousePos.y - drag_y_);
    drag_x_ = io.MousePos.x;
    drag_y_ = io.MousePos.y;
  }
  return quit;
}

}  // namespace jelly::app
