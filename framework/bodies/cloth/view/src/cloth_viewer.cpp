// The cloth's controls in jelly-lab: keys 1–4 pin and unpin the corners, the arrows drive the
// first kinematic sphere, S stops it (Space stays play/pause); the Cloth panel section; and the
// smoke test's check of those keys. They act on every run (comparison mode has several).
#include <cstdio>
#include <string>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "jelly/bodies/cloth/view/cloth_controls.hpp"
#include "jelly/bodies/cloth/view/cloth_view.hpp"
#include "jelly/cloth_physics.hpp"
#include "jelly/session/simulation_run.hpp"

namespace jelly::cloth_view {

namespace {

using render::ViewerContext;
using session::SimulationRun;

/// The world of the front run, null when it failed to build.
World* front_world(const ViewerContext& c) {
  if (c.runs.empty() || !c.runs.front()->ok()) return nullptr;
  return &c.runs.front()->simulator()->world();
}

class ClothControls final : public render::BodyControls {
 public:
  void reset() override {
    driving_ = false;  // new worlds: the spheres follow their schedules again
    drive_ = Vec3::Zero();
  }
  void handle_keys(const ViewerContext& c) override;
  void draw_panel(const ViewerContext& c) override;
  int smoke_check(const ViewerContext& c) override;

 private:
  /// Pins or frees corner `corner` (0–3) of the cloth in every run; false when there is none.
  static bool toggle_pin(const ViewerContext& c, int corner);
  static bool has_kinematic_sphere(const ViewerContext& c) {
    const World* w = front_world(c);
    return w && first_kinematic_sphere(*w) >= 0;
  }
  /// Drives the first kinematic sphere of every run at `velocity`.
  bool drive_all(const ViewerContext& c, const Vec3& velocity);
  bool press_arrow(const ViewerContext& c, Arrow arrow) {
    return has_kinematic_sphere(c) &&
           drive_all(c, arrow_drive(drive_, arrow, c.camera_yaw_degrees));
  }
  bool stop_sphere(const ViewerContext& c) {
    return has_kinematic_sphere(c) && drive_all(c, Vec3::Zero());
  }
  int check_arrows(const ViewerContext& c, std::string& said);

  bool driving_ = false;
  Vec3 drive_{0.0, 0.0, 0.0};
};

bool ClothControls::toggle_pin(const ViewerContext& c, int corner) {
  bool any = false;
  for (SimulationRun* r : c.runs)
    if (r->ok()) any = toggle_corner_pin(r->simulator()->world(), corner).has_value() || any;
  return any;
}

bool ClothControls::drive_all(const ViewerContext& c, const Vec3& velocity) {
  bool any = false;
  for (SimulationRun* r : c.runs)
    if (r->ok()) any = drive_first_kinematic_sphere(r->simulator()->world(), velocity) || any;
  if (any) {
    driving_ = true;
    drive_ = velocity;
  }
  return any;
}

void ClothControls::handle_keys(const ViewerContext& c) {
  static constexpr int kPinKeys[4] = {GLFW_KEY_1, GLFW_KEY_2, GLFW_KEY_3, GLFW_KEY_4};
  for (int corner = 0; corner < 4; ++corner)
    if (ImGui::IsKeyPressed(kPinKeys[corner], false)) toggle_pin(c, corner);
  if (ImGui::IsKeyPressed(GLFW_KEY_LEFT, false)) press_arrow(c, Arrow::Left);
  if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT, false)) press_arrow(c, Arrow::Right);
  if (ImGui::IsKeyPressed(GLFW_KEY_UP, false)) press_arrow(c, Arrow::Up);
  if (ImGui::IsKeyPressed(GLFW_KEY_DOWN, false)) press_arrow(c, Arrow::Down);
  if (ImGui::IsKeyPressed(GLFW_KEY_S, false)) stop_sphere(c);
}

/// The corner pins (keys 1–4) and the kinematic sphere's drive (arrows, S).
void ClothControls::draw_panel(const ViewerContext& c) {
  const World* world = front_world(c);  // read only: pins change through toggle_pin
  if (!world || cloth_physics(*world).cloths().empty()) return;
  const ClothGrid& grid = cloth_physics(*world).cloths().front();
  ImGui::TextUnformatted("pinned corners (keys 1-4):");
  static const char* corners[4] = {"1 (0,0)", "2 (0,n-1)", "3 (n-1,0)", "4 (n-1,n-1)"};
  for (int corner = 0; corner < 4; ++corner) {
    bool pinned = cloth_physics(*world).is_pinned(corner_particle(grid, corner));
    if (corner > 0) ImGui::SameLine();
    if (ImGui::Checkbox(corners[corner], &pinned)) toggle_pin(c, corner);
  }
  if (!has_kinematic_sphere(c)) return;
  ImGui::Text("arrows: drive the sphere (%.3g m/s along x/z), S: stop", kDriveSpeed);
  if (driving_)
    ImGui::Text("driven at (%.3g, %.3g, %.3g) m/s; Reset (R) restores its schedule", drive_.x(),
                drive_.y(), drive_.z());
  else
    ImGui::TextDisabled("following the scene's schedule");
  if (ImGui::Button("Stop sphere (S)")) stop_sphere(c);
}

/// Keys 1–4 flip each corner's pin (and back), the right arrow moves the kinematic sphere by
/// speed × time, S stops it.
int ClothControls::smoke_check(const ViewerContext& c) {
  const World* world = front_world(c);  // read only: pins change through toggle_pin
  if (!world || cloth_physics(*world).cloths().empty()) return 0;
  const ClothGrid& grid = cloth_physics(*world).cloths().front();
  int failures = 0;
  const auto fail = [&](const std::string& what) {
    std::printf("smoke: scene %s: %s\n", c.scene_name.c_str(), what.c_str());
    ++failures;
  };
  for (int corner = 0; corner < 4; ++corner) {
    const int p = corner_particle(grid, corner);
    const bool before = cloth_physics(*world).is_pinned(p);
    toggle_pin(c, corner);
    if (cloth_physics(*world).is_pinned(p) == before)
      fail("key " + std::to_string(corner + 1) + " did not change the pin of particle " +
           std::to_string(p));
    toggle_pin(c, corner);
    if (cloth_physics(*world).is_pinned(p) != before)
      fail("key " + std::to_string(corner + 1) + " twice did not restore particle " +
           std::to_string(p));
  }
  std::string arrows;
  if (has_kinematic_sphere(c)) failures += check_arrows(c, arrows);
  std::printf("smoke: scene %-35s keys 1-4 toggled the corner pins%s\n", c.scene_name.c_str(),
              arrows.c_str());
  return failures;
}

/// Right arrow for 0.1 s: the sphere moves speed × 0.1 s along the view's right axis; S stops it.
/// Steps are whole, so the distance is within one step's travel.
int ClothControls::check_arrows(const ViewerContext& c, std::string& said) {
  SimulationRun& run = *c.runs.front();
  World& world = run.simulator()->world();
  int failures = 0;
  const auto fail = [&](const std::string& what) {
    std::printf("smoke: scene %s: %s\n", c.scene_name.c_str(), what.c_str());
    ++failures;
  };
  const int sphere = first_kinematic_sphere(world);
  const Vec3 expected = arrow_drive(Vec3::Zero(), Arrow::Right, c.camera_yaw_degrees);
  const Vec3 c0 = cloth_physics(world).sphere(sphere).center;
  const double t0 = run.time();
  press_arrow(c, Arrow::Right);
  run.advance_to(t0 + 0.1);
  const Vec3 moved = cloth_physics(world).sphere(sphere).center - c0;
  const double tolerance = 1.5 * run.step() * kDriveSpeed + 1e-9;
  if ((moved - expected * (run.time() - t0)).norm() > tolerance)
    fail("the right arrow moved the sphere by (" + std::to_string(moved.x()) + ", " +
         std::to_string(moved.y()) + ", " + std::to_string(moved.z()) + ") m in " +
         std::to_string(run.time() - t0) + " s");
  stop_sphere(c);
  const Vec3 c1 = cloth_physics(world).sphere(sphere).center;
  run.advance_to(run.time() + 0.1);
  if ((cloth_physics(world).sphere(sphere).center - c1).norm() > 1e-12)
    fail("S did not stop the sphere");
  char buf[128];
  std::snprintf(buf, sizeof buf, ", right arrow moved the sphere %.3f m, S stopped it",
                moved.norm());
  said = buf;
  return failures;
}

}  // namespace

std::unique_ptr<render::BodyControls> make_controls() { return std::make_unique<ClothControls>(); }

}  // namespace jelly::cloth_view
