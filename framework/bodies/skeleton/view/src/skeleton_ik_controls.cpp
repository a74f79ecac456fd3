// An ik scene's controls in jelly-lab (skeleton_ik_controls.hpp): the balls dragged with the mouse
// in the plane facing the camera and moved with keys, each chain's bones picked by name, the
// solve's outcome live, the settings, Reset, and the plot of the last solve's error. The solves
// are the player's (SkeletonPlayer::ik_update, through solve_ik as `jelly run`).
#include "skeleton_ik_controls.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "jelly/bodies/skeleton/view/ik_target.hpp"
#include "jelly/bodies/skeleton/view/skeleton_view.hpp"

namespace jelly::skeleton_view {

namespace {

using render::ViewerContext;

const ImVec4 kRed{1.0f, 0.42f, 0.38f, 1.0f};
const ImVec4 kGreen{0.35f, 0.90f, 0.45f, 1.0f};

/// The mouse in the first run's viewport's pixels.
Eigen::Vector2d mouse_in_view(const ViewerContext& c) {
  return c.mouse - Eigen::Vector2d(c.viewport.x, c.viewport.y);
}

/// The players that are in mode ik with as many chains as `first` (comparison mode).
std::vector<SkeletonPlayer*> alike(const std::vector<SkeletonPlayer*>& players,
                                   const SkeletonPlayer& first) {
  std::vector<SkeletonPlayer*> out;
  for (SkeletonPlayer* p : players)
    if (p->mode() == SkeletonMode::Ik && p->ik_chain_count() == first.ik_chain_count())
      out.push_back(p);
  return out;
}

std::string chain_label(const SkeletonPlayer& p, std::size_t c) {
  const IkChainState& s = p.ik_chain(c);
  const auto& bones = p.skeleton().bones;
  return std::to_string(c) + ": " + bones[static_cast<std::size_t>(s.start)].name + " -> " +
         bones[static_cast<std::size_t>(s.end)].name;
}

/// A combo of the skeleton's bones by name; true when `bone` changed.
bool bone_combo(const char* label, const SkeletonPlayer& p, int& bone) {
  const auto& bones = p.skeleton().bones;
  bool changed = false;
  if (ImGui::BeginCombo(label, bones[static_cast<std::size_t>(bone)].name.c_str())) {
    for (int b = 0; b < static_cast<int>(bones.size()); ++b)
      if (ImGui::Selectable(bones[static_cast<std::size_t>(b)].name.c_str(), b == bone)) {
        changed = b != bone;
        bone = b;
      }
    ImGui::EndCombo();
  }
  return changed;
}

}  // namespace

void IkControls::nudge(const ViewerContext& c, const std::vector<SkeletonPlayer*>& players,
                       int axis, double steps) {
  if (players.empty() || !c.camera) return;
  SkeletonPlayer& first = *players.front();
  if (chain_ >= first.ik_chain_count()) return;
  const Vec3 move = steps * kTargetStepShare * figure_size(first) * camera_axis(*c.camera, axis);
  for (SkeletonPlayer* p : alike(players, first))
    p->set_ik_target(chain_, p->ik_target(chain_) + move);
}

void IkControls::handle_keys(const ViewerContext& c, const std::vector<SkeletonPlayer*>& players) {
  if (players.empty()) return;
  const std::size_t n = players.front()->ik_chain_count();
  if (n == 0) return;
  if (ImGui::IsKeyPressed(GLFW_KEY_TAB, false)) chain_ = (chain_ + 1) % n;
  chain_ = std::min(chain_, n - 1);
  if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT, true)) nudge(c, players, 0, +1);
  if (ImGui::IsKeyPressed(GLFW_KEY_LEFT, true)) nudge(c, players, 0, -1);
  if (ImGui::IsKeyPressed(GLFW_KEY_UP, true)) nudge(c, players, 1, +1);
  if (ImGui::IsKeyPressed(GLFW_KEY_DOWN, true)) nudge(c, players, 1, -1);
  if (ImGui::IsKeyPressed(GLFW_KEY_PAGE_UP, true)) nudge(c, players, 2, +1);
  if (ImGui::IsKeyPressed(GLFW_KEY_PAGE_DOWN, true)) nudge(c, players, 2, -1);
}

bool IkControls::mouse_down(const ViewerContext& c, SkeletonPlayer& first) {
  if (!c.camera || first.ik_chain_count() == 0) return false;
  std::vector<Vec3> targets;
  for (std::size_t i = 0; i < first.ik_chain_count(); ++i) targets.push_back(first.ik_target(i));
  dragged_ = target_near(*c.camera, c.viewport.width, c.viewport.height, mouse_in_view(c), targets,
                         kPickRadiusPixels);
  if (dragged_ >= 0) chain_ = static_cast<std::size_t>(dragged_);
  return dragged_ >= 0;
}

void IkControls::mouse_drag(const ViewerContext& c, const std::vector<SkeletonPlayer*>& players) {
  if (dragged_ < 0 || players.empty() || !c.camera) return;
  SkeletonPlayer& first = *players.front();
  const auto chain = static_cast<std::size_t>(dragged_);
  if (chain >= first.ik_chain_count()) return;
  const std::optional<Vec3> at = point_under_mouse(*c.camera, c.viewport.width, c.viewport.height,
                                                   mouse_in_view(c), first.ik_target(chain));
  if (!at || (*at - first.ik_target(chain)).norm() == 0.0) return;  // no move: no solve
  for (SkeletonPlayer* p : alike(players, first)) p->set_ik_target(chain, *at);
}

/// One chain: its start and end bones, its target, and its last solve's outcome.
void IkControls::chain_section(const std::vector<SkeletonPlayer*>& players, SkeletonPlayer& p,
                               std::size_t c) {
  ImGui::PushID(static_cast<int>(c));
  const IkChainState& s = p.ik_chain(c);
  if (ImGui::RadioButton(chain_label(p, c).c_str(), chain_ == c)) chain_ = c;
  int start = s.start, end = s.end;
  bool bones = bone_combo("start bone", p, start);
  bones |= bone_combo("end bone", p, end);
  if (bones)
    for (SkeletonPlayer* q : players) q->set_ik_bones(c, start, end);
  const Vec3 t = p.ik_target(c);
  float target[3] = {static_cast<float>(t.x()), static_cast<float>(t.y()),
                     static_cast<float>(t.z())};
  if (ImGui::DragFloat3("target", target, 0.005f, 0.0f, 0.0f, "%.4f"))
    for (SkeletonPlayer* q : players) q->set_ik_target(c, Vec3(target[0], target[1], target[2]));
  if (!s.chain_error.empty()) ImGui::TextColored(kRed, "%s", s.chain_error.c_str());
  const IkSolveRecord& r = p.ik_record(c);
  if (!r.error.empty() && r.error != s.chain_error) ImGui::TextColored(kRed, "%s", r.error.c_str());
  if (r.solved) {
    ImGui::TextColored(r.result.stable ? kGreen : kRed, "%s",
                       r.result.stable ? "Stable" : "Unstable");
    ImGui::SameLine();
    ImGui::Text("%d updates, error %.4g, %zu bones", r.result.updates, r.result.error,
                s.bones.size());
  }
  ImGui::PopID();
}

/// Limits, step, epsilon, max_iterations and Reset, for every chain.
void IkControls::settings_section(const std::vector<SkeletonPlayer*>& players, SkeletonPlayer& p) {
  skeleton::IkSettings s = p.ik_settings();
  bool changed = ImGui::Checkbox("limits (the bonus)", &s.limits);
  float step = static_cast<float>(s.step), epsilon = static_cast<float>(s.epsilon);
  if (ImGui::SliderFloat("step", &step, 0.001f, 1.0f, "%.3f", ImGuiSliderFlags_Logarithmic)) {
    s.step = step;
    changed = true;
  }
  if (ImGui::SliderFloat("epsilon", &epsilon, 1e-6f, 1e-1f, "%.1e", ImGuiSliderFlags_Logarithmic)) {
    s.epsilon = epsilon;
    changed = true;
  }
  changed |= ImGui::SliderInt("max_iterations", &s.max_iterations, 0, 5000);
  if (changed)
    for (SkeletonPlayer* q : players) q->set_ik_settings(s);
  if (ImGui::Button("Reset (the scene's targets, chains, settings)"))
    for (SkeletonPlayer* q : players) q->ik_reset();
}

/// The selected chain's last solve: log10 of |x* − p| against the update.
void IkControls::error_plot(SkeletonPlayer& p) {
  const IkSolveRecord& r = p.ik_record(chain_);
  if (r.errors.empty()) return;
  std::vector<float> log_error;
  log_error.reserve(r.errors.size());
  for (double e : r.errors) log_error.push_back(static_cast<float>(std::log10(std::max(e, 1e-12))));
  const auto [lo, hi] = std::minmax_element(log_error.begin(), log_error.end());
  ImGui::PlotLines("##ik_error", log_error.data(), static_cast<int>(log_error.size()), 0, nullptr,
                   *lo, std::max(*hi, *lo + 1e-3f),
                   ImVec2(ImGui::GetContentRegionAvail().x, 110.0f));
  ImGui::Text("chain %zu: log10 error from %.3g to %.3g over %d updates", chain_, *hi, *lo,
              r.result.updates);
}

void IkControls::draw_panel(const ViewerContext&, const std::vector<SkeletonPlayer*>& all) {
  if (all.empty()) return;
  SkeletonPlayer& p = *all.front();
  const std::vector<SkeletonPlayer*> players = alike(all, p);
  if (p.ik_chain_count() == 0) return;
  chain_ = std::min(chain_, p.ik_chain_count() - 1);
  ImGui::TextWrapped(
      "Drag a ball (magenta) with the mouse; arrows move the selected chain's ball in the view's "
      "plane, Page Up/Down away/toward, Tab the next chain. Each move is solved at once, from the "
      "posture shown.");
  for (std::size_t c = 0; c < p.ik_chain_count(); ++c) {
    ImGui::Separator();
    chain_section(players, p, c);
  }
  ImGui::Separator();
  settings_section(players, p);
  error_plot(p);
}

/// A press on chain 0's target and a drag of (30, −20) pixels, as the viewer's mouse would: the
/// target ends under the mouse, in the plane it was in facing the camera.
int IkControls::smoke_drag(const ViewerContext& c, SkeletonPlayer& p) {
  if (c.viewport.width <= 0 || c.viewport.height <= 0) return 0;
  const auto at = c.camera->project(p.ik_target(0), c.viewport.width, c.viewport.height);
  if (!at) return 0;
  ViewerContext mouse = c;
  mouse.mouse = *at + Eigen::Vector2d(c.viewport.x, c.viewport.y);
  const Vec3 before = p.ik_target(0);
  if (!mouse_down(mouse, p) || dragged_ != 0) {
    std::printf("smoke: scene %s: a press on the target did not take it\n", c.scene_name.c_str());
    return 1;
  }
  mouse.mouse += Eigen::Vector2d(30.0, -20.0);
  mouse_drag(mouse, {&p});
  mouse_up();
  p.ik_update();
  const auto now = c.camera->project(p.ik_target(0), c.viewport.width, c.viewport.height);
  const double off_plane = (p.ik_target(0) - before).dot(camera_axis(*c.camera, 2));
  if (!now || (*now - (*at + Eigen::Vector2d(30.0, -20.0))).norm() > 0.5 ||
      std::abs(off_plane) > 1e-6 * (1.0 + before.norm())) {
    std::printf("smoke: scene %s: the dragged target is not under the mouse\n",
                c.scene_name.c_str());
    return 1;
  }
  return 0;
}

int IkControls::smoke_check(const ViewerContext& c, SkeletonPlayer& p) {
  int failures = 0;
  const auto fail = [&](const std::string& what) {
    std::printf("smoke: scene %s: %s\n", c.scene_name.c_str(), what.c_str());
    ++failures;
  };
  if (p.ik_chain_count() == 0 || p.frame_count() == 0 || !c.camera) return 0;
  p.ik_update();
  chain_ = 0;
  const Vec3 target = p.ik_target(0);
  const skeleton::Posture before = p.output().frames[static_cast<std::size_t>(p.frame())];
  const long solves = p.ik_solve_count();
  for (int press = 0; press < 3; ++press) nudge(c, {&p}, 0, +1);  // Right, three times
  if (!p.ik_update()) fail("moving the target did not solve");
  if (!((p.ik_target(0) - target).norm() > 0.0)) fail("Right did not move the target");
  const bool moved = p.output().frames[static_cast<std::size_t>(p.frame())].angles != before.angles;
  const IkSolveRecord& r = p.ik_record(0);
  if (!r.solved) fail("the solve failed: " + r.error);
  // A stable solve moved the skeleton and shrank the error; an unstable one (ik-unreachable)
  // put the posture back.
  if (r.solved && r.result.stable && !moved) fail("the solve did not move the skeleton");
  if (r.solved && r.result.stable && !(r.errors.size() > 1 && r.result.error < r.errors.front()))
    fail("the solve did not shrink the error");
  if (r.solved && !r.result.stable && p.ik_settings().restore && moved && p.ik_chain_count() == 1)
    fail("an unstable solve did not put the posture back");
  if (p.ik_update() || p.ik_solve_count() != solves + static_cast<long>(p.ik_chain_count()))
    fail("an idle frame solved again");
  failures += smoke_drag(c, p);
  std::printf(
      "smoke: scene %-35s Right x3 and a drag moved the target %.3g; the last solve: "
      "%d updates, %s, error %.3g -> %.3g\n",
      c.scene_name.c_str(), (p.ik_target(0) - target).norm(), r.result.updates,
      r.result.stable ? "stable" : "unstable", r.errors.empty() ? 0.0 : r.errors.front(),
      r.result.error);
  p.ik_reset();
  return failures;
}

}  // namespace jelly::skeleton_view
