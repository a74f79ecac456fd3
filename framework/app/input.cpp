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
    // The body kinds' own keys (each ignores them in scenes without its bodies).
    const render::ViewerContext context = s.viewer_context();
    for (auto& [view, controls] : s.body_controls) controls->handle_keys(context);
  }
  if (!io.WantCaptureMouse) {
    if (ImGui::IsMouseClicked(0)) {
      dragging_ = true;
      drag_x_ = io.MousePos.x;
      drag_y_ = io.MousePos.y;
      // A body kind may take the drag (e.g. a target under the mouse); else the camera orbits.
      const render::ViewerContext context = s.viewer_context();
      for (auto& [view, controls] : s.body_controls)
        if (!drag_owner_ && controls->mouse_down(context)) drag_owner_ = controls.get();
    }
    if (io.MouseWheel != 0.0f) s.camera.zoom(io.MouseWheel);
  }
  if (!ImGui::IsMouseDown(0)) {
    if (drag_owner_) drag_owner_->mouse_up(s.viewer_context());
    drag_owner_ = nullptr;
    dragging_ = false;
  }
  if (dragging_ && drag_owner_) {
    drag_owner_->mouse_drag(s.viewer_context());
  } else if (dragging_) {
    s.camera.orbit(io.MousePos.x - drag_x_, io.MousePos.y - drag_y_);
    drag_x_ = io.MousePos.x;
    drag_y_ = io.MousePos.y;
  }
  return quit;
}

}  // namespace jelly::app
