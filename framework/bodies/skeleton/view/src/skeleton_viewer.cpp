// The skeleton's controls in jelly-lab: the Skeleton panel section (play, pause, stop, step back
// and forward, the frame slider, the speed; in a warp the keyframe and frame-count sliders that
// re-warp through the tasks, and the original beside or over the warped motion; the bone picker
// with the bone's angles and position and a plot of its angle or height over time, original
// against warped; an ik scene's section, skeleton_ik_controls.cpp), the keys, the ik target's
// drag, and the smoke test's check. They act on every run.
#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <string>
#include <vector>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "jelly/bodies/skeleton/view/skeleton_view.hpp"
#include "jelly/session/simulation_run.hpp"
#include "skeleton_ik_controls.hpp"

namespace jelly::skeleton_view {

namespace {

using render::ViewerContext;
using session::SimulationRun;

const ImVec4 kRed{1.0f, 0.42f, 0.38f, 1.0f};

ImU32 color_of(const Eigen::Vector3f& c) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c.x(), c.y(), c.z(), 1.0f));
}

/// The players of the runs that built.
std::vector<SkeletonPlayer*> players(const ViewerContext& c) {
  std::vector<SkeletonPlayer*> out;
  for (SimulationRun* r : c.runs)
    if (r->ok())
      if (SkeletonPlayer* p = find_skeleton_player(r->simulator()->world())) out.push_back(p);
  return out;
}

class SkeletonControls final : public render::BodyControls {
 public:
  void reset() override {
    original_key_.clear();
    shown_key_.clear();
    ik_.reset();
  }
  void handle_keys(const ViewerContext& c) override;
  void draw_panel(const ViewerContext& c) override;
  int smoke_check(const ViewerContext& c) override;
  /// An ik scene's live solves: what the keys, the mouse and the panel moved is solved once.
  void update(const ViewerContext& c) override {
    for (SkeletonPlayer* p : players(c)) p->ik_update();
  }
  bool mouse_down(const ViewerContext& c) override {
    const std::vector<SkeletonPlayer*> all = players(c);
    return !all.empty() && ik_.mouse_down(c, *all.front());
  }
  void mouse_drag(const ViewerContext& c) override { ik_.mouse_drag(c, players(c)); }
  void mouse_up(const ViewerContext&) override { ik_.mouse_up(); }

 private:
  void playback(const ViewerContext& c, SkeletonPlayer& p);
  void warp_sliders(const ViewerContext& c, SkeletonPlayer& p);
  void bone_picker(SkeletonPlayer& p);
  void plot(SkeletonPlayer& p);

  IkControls ik_;
  BoneQuantity quantity_ = BoneQuantity::Rx;
  std::string warp_error_;
  // What the cached series were made of: the original's does not change while a warp slider
  // moves, so a moved slider computes only the warped one.
  std::string original_key_, shown_key_;
  std::vector<float> original_, shown_;
};

void SkeletonControls::handle_keys(const ViewerContext& c) {
  const std::vector<SkeletonPlayer*> all = players(c);
  const bool ik = !all.empty() && all.front()->mode() == SkeletonMode::Ik;
  if (ik) ik_.handle_keys(c, all);  // the arrows move the target (the panel's - and + step)
  for (SkeletonPlayer* p : all) {
    if (!ik && ImGui::IsKeyPressed(GLFW_KEY_RIGHT, true)) p->step(+1);
    if (!ik && ImGui::IsKeyPressed(GLFW_KEY_LEFT, true)) p->step(-1);
    if (ImGui::IsKeyPressed(GLFW_KEY_K, false)) p->set_playing(!p->playing());
    if (ImGui::IsKeyPressed(GLFW_KEY_HOME, false)) p->stop();
  }
}

/// Play/pause, stop, − and +, the frame slider and the speed (every run follows the first).
void SkeletonControls::playback(const ViewerContext& c, SkeletonPlayer& p) {
  const std::vector<SkeletonPlayer*> all = players(c);
  if (ImGui::Button(p.playing() ? "Pause (K)" : "Play (K)"))
    for (SkeletonPlayer* q : all) q->set_playing(!p.playing());
  ImGui::SameLine();
  if (ImGui::Button("Stop (Home)"))
    for (SkeletonPlayer* q : all) q->stop();
  ImGui::SameLine();
  if (ImGui::Button(" - "))
    for (SkeletonPlayer* q : all) q->step(-1);
  ImGui::SameLine();
  if (ImGui::Button(" + "))
    for (SkeletonPlayer* q : all) q->step(+1);
  int frame = p.frame();
  if (ImGui::SliderInt("frame", &frame, 0, std::max(0, p.frame_count() - 1)))
    for (SkeletonPlayer* q : all) {
      q->seek(frame);
      q->set_playing(false);
    }
  float speed = static_cast<float>(p.speed());
  if (ImGui::SliderFloat("speed", &speed, 0.1f, 4.0f, "%.2fx", ImGuiSliderFlags_Logarithmic))
    for (SkeletonPlayer* q : all) q->set_speed(speed);
  ImGui::Text("frame %d of %d at %g fps, %s", p.frame(), p.frame_count(), p.fps(),
              p.playing() ? "playing" : "paused");
}

/// K_in, K_out and M, re-warped through the tasks as they move; the original beside or over.
void SkeletonControls::warp_sliders(const ViewerContext& c, SkeletonPlayer& p) {
  skeleton::TimeWarp w = p.warp();
  bool keyframe = w.has_keyframe();
  bool changed = ImGui::Checkbox("keyframe (else uniform)", &keyframe);
  if (changed && keyframe) {
    w.keyframe_in = std::clamp(p.scene_warp().keyframe_in, 1, w.input_frames - 2);
    w.keyframe_out = std::clamp(p.scene_warp().keyframe_out, 1, w.output_frames - 2);
    if (!p.scene_warp().has_keyframe()) w.keyframe_in = w.input_frames / 2;
    if (!p.scene_warp().has_keyframe()) w.keyframe_out = w.output_frames / 2;
  } else if (changed) {
    w.keyframe_in = w.keyframe_out = -1;
  }
  changed |= ImGui::SliderInt("frames M", &w.output_frames, 2, 4 * w.input_frames);
  if (keyframe) {
    changed |= ImGui::SliderInt("K_in", &w.keyframe_in, 1, w.input_frames - 2);
    changed |= ImGui::SliderInt("K_out", &w.keyframe_out, 1, std::max(1, w.output_frames - 2));
    w.keyframe_out = std::clamp(w.keyframe_out, 1, std::max(1, w.output_frames - 2));
  }
  if (ImGui::Button("The scene's warp")) {
    w = p.scene_warp();
    changed = true;
  }
  if (changed)
    for (SkeletonPlayer* q : players(c)) warp_error_ = q->set_warp(w);
  if (!warp_error_.empty()) ImGui::TextColored(kRed, "%s", warp_error_.c_str());
  ViewSettings& s = view_settings();
  ImGui::Checkbox("original too", &s.show_original);
  ImGui::SameLine();
  ImGui::Checkbox("side by side (else overlaid)", &s.side_by_side);
  ImGui::TextColored(ImVec4(kOriginalBone.x(), kOriginalBone.y(), kOriginalBone.z(), 1),
                     "original");
  ImGui::SameLine();
  ImGui::TextColored(ImVec4(kBone.x(), kBone.y(), kBone.z(), 1), "warped");
}

/// The bone combo; the picked bone's local angles and global start and end at the shown frame.
void SkeletonControls::bone_picker(SkeletonPlayer& p) {
  ViewSettings& s = view_settings();
  const std::vector<skeleton::Bone>& bones = p.skeleton().bones;
  const int n = static_cast<int>(bones.size());
  const char* current = s.picked_bone >= 0 && s.picked_bone < n
                            ? bones[static_cast<std::size_t>(s.picked_bone)].name.c_str()
                            : "(none)";
  if (ImGui::BeginCombo("bone", current)) {
    if (ImGui::Selectable("(none)", s.picked_bone < 0)) s.picked_bone = -1;
    for (int b = 0; b < n; ++b)
      if (ImGui::Selectable(bones[static_cast<std::size_t>(b)].name.c_str(), b == s.picked_bone))
        s.picked_bone = b;
    ImGui::EndCombo();
  }
  if (s.picked_bone < 0 || s.picked_bone >= n || p.frame_count() == 0) return;
  const auto b = static_cast<std::size_t>(s.picked_bone);
  const Vec3& a = p.output().frames[static_cast<std::size_t>(p.frame())].angles[b];
  ImGui::Text("local angles (%.2f, %.2f, %.2f) deg", a.x(), a.y(), a.z());
  if (const skeleton::BoneFrames* f = p.output_frames(p.frame())) {
    ImGui::Text("start (%.3f, %.3f, %.3f)", f->start[b].x(), f->start[b].y(), f->start[b].z());
    ImGui::Text("end   (%.3f, %.3f, %.3f)", f->end[b].x(), f->end[b].y(), f->end[b].z());
  }
  plot(p);
}

/// The picked bone's angle or height over the output frames, original (red) against the shown
/// motion (blue), and the shown frame as a line.
void SkeletonControls::plot(SkeletonPlayer& p) {
  static const char* names[] = {"rx", "ry", "rz", "end height"};
  int q = static_cast<int>(quantity_);
  ImGui::Combo("plot", &q, names, 4);
  quantity_ = static_cast<BoneQuantity>(q);
  const int bone = view_settings().picked_bone;
  const skeleton::TimeWarp& w = p.warp();
  const std::string original =
      std::to_string(bone) + "/" + std::to_string(q) + "/" + std::to_string(p.frame_count());
  const std::string shown =
      original + "/" + std::to_string(w.keyframe_in) + "/" + std::to_string(w.keyframe_out);
  if (original != original_key_) {
    original_ = bone_series(p, bone, quantity_, true);
    original_key_ = original;
  }
  if (shown != shown_key_) {
    shown_ = bone_series(p, bone, quantity_, false);
    shown_key_ = shown;
  }
  if (shown_.empty()) return;
  float lo = FLT_MAX, hi = -FLT_MAX;
  for (const auto* v : {&original_, &shown_})
    for (float x : *v) {
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  if (hi - lo < 1e-6f) hi = lo + 1.0f;
  const ImVec2 size(ImGui::GetContentRegionAvail().x, 110.0f);
  const ImVec2 at = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("plot_area", size);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(at, ImVec2(at.x + size.x, at.y + size.y), IM_COL32(25, 28, 36, 255));
  const auto point = [&](std::size_t i, float v) {
    const float x =
        at.x + size.x * static_cast<float>(i) / std::max<std::size_t>(1, shown_.size() - 1);
    return ImVec2(x, at.y + size.y * (1.0f - (v - lo) / (hi - lo)));
  };
  for (const auto& [v, c] : {std::pair{&original_, kOriginalBone}, std::pair{&shown_, kBone}}) {
    std::vector<ImVec2> line;
    for (std::size_t i = 0; i < v->size(); ++i) line.push_back(point(i, (*v)[i]));
    dl->AddPolyline(line.data(), static_cast<int>(line.size()), color_of(c), 0, 1.5f);
  }
  const ImVec2 now = point(static_cast<std::size_t>(p.frame()), lo);
  dl->AddLine(ImVec2(now.x, at.y), ImVec2(now.x, at.y + size.y), IM_COL32(240, 240, 240, 160));
  ImGui::Text("%s from %.3g to %.3g (red: original, blue: %s)", names[q], lo, hi,
              p.mode() == SkeletonMode::Warp ? "warped" : "played");
}

void SkeletonControls::draw_panel(const ViewerContext& c) {
  const std::vector<SkeletonPlayer*> all = players(c);
  if (all.empty()) return;
  SkeletonPlayer& p = *all.front();
  if (!p.problem().empty()) ImGui::TextColored(kRed, "%s", p.problem().c_str());
  playback(c, p);
  if (p.mode() == SkeletonMode::Warp) {
    ImGui::Separator();
    warp_sliders(c, p);
  }
  if (p.mode() == SkeletonMode::Ik) {
    ImGui::Separator();
    ik_.draw_panel(c, all);
  }
  ImGui::Separator();
  bone_picker(p);
}

/// + and − step the frame, the slider seeks, and in a warp moving K_out re-warps: the output at
/// K_out is then the input's K_in.
int SkeletonControls::smoke_check(const ViewerContext& c) {
  const std::vector<SkeletonPlayer*> all = players(c);
  if (all.empty()) return 0;
  SkeletonPlayer& p = *all.front();
  int failures = 0;
  const auto fail = [&](const std::string& what) {
    std::printf("smoke: scene %s: %s\n", c.scene_name.c_str(), what.c_str());
    ++failures;
  };
  if (!p.problem().empty()) fail("the skeleton is not drawn: " + p.problem());
  if (p.mode() == SkeletonMode::Ik && p.problem().empty()) failures += ik_.smoke_check(c, p);
  if (p.frame_count() < 3) return failures;
  p.seek(1);
  p.step(+1);
  if (p.frame() != 2) fail("+ did not step to frame 2");
  p.step(-1);
  if (p.frame() != 1) fail("- did not step back to frame 1");
  std::string warped;
  if (p.mode() == SkeletonMode::Warp) {
    // The sliders' re-warp takes effect: the new frame count and keyframe (what the tasks then
    // compute is theirs to get right: a student's stubs pass here too).
    skeleton::TimeWarp w = p.warp();
    w.output_frames = w.input_frames + 10;
    w.keyframe_in = w.input_frames / 2;
    w.keyframe_out = w.output_frames / 3;
    if (std::string e = p.set_warp(w); !e.empty()) fail("the warp sliders were refused: " + e);
    if (p.warp().keyframe_out != w.keyframe_out ||
        (p.problem().empty() && p.frame_count() != w.output_frames))
      fail("the warp sliders did not re-warp to " + std::to_string(w.output_frames) + " frames");
    p.set_warp(p.scene_warp());
    warped = ", re-warped K_in " + std::to_string(w.keyframe_in) + " -> K_out " +
             std::to_string(w.keyframe_out);
  }
  p.set_playing(true);
  std::printf("smoke: scene %-35s skeleton drawn, %d frames, +/- stepped%s\n", c.scene_name.c_str(),
              p.frame_count(), warped.c_str());
  return failures;
}

}  // namespace

std::unique_ptr<render::BodyControls> make_controls() {
  return std::make_unique<SkeletonControls>();
}

}  // namespace jelly::skeleton_view
