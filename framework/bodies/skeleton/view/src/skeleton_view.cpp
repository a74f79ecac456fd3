// The skeleton kind's view: framing, the caption line and the viewer's names and help for a
// skeleton scene (its drawable: skeleton_drawable.cpp; its panel and keys: skeleton_viewer.cpp,
// in jelly_skeleton_view_controls).
#include <filesystem>
#include <string>

#include "jelly/bodies/skeleton/view/skeleton_view.hpp"
#include "jelly/session/captions.hpp"
#include "jelly/skeleton_scene.hpp"

namespace jelly::skeleton_view {

namespace {

using session::format_number;

class SkeletonView final : public render::BodyView {
 public:
  std::string_view kind() const override { return "skeleton"; }
  bool present(const World& world) const override { return find_skeleton_player(world) != nullptr; }
  std::unique_ptr<render::BodyDrawable> make_drawable(const World& world) const override {
    return std::make_unique<SkeletonDrawable>(world);
  }
  bool frame(const World& world, const std::function<void(const Vec3&)>& grow) const override;
  std::string caption_body(const SceneSpec& sc) const override;

  std::string_view surface_label() const override { return "skeleton"; }
  bool shows_spring_type(SpringType) const override { return false; }
  std::string_view panel_title() const override { return "Skeleton"; }
  std::string_view panel_id() const override { return "skeleton"; }
  std::string_view keys_help() const override {
    return "skeleton scenes: left/right step a frame back/forward, K play/pause the motion, "
           "Home stop; ik scenes: drag a ball with the mouse, arrows move the selected target "
           "along the view's right and up, PgUp/PgDn away/toward, Tab the next chain";
  }
};

/// Every bone end of the whole input and output motions (the walk's path, the warp's original
/// beside it), or the root's path when there is no forward kinematics.
bool SkeletonView::frame(const World& world, const std::function<void(const Vec3&)>& grow) const {
  const SkeletonPlayer* player = find_skeleton_player(world);
  if (!player) return false;
  const std::vector<Vec3>& ends = player->extent();
  for (const Vec3& e : ends) grow(e);
  if (ends.empty())
    for (const skeleton::Posture& p : player->input().frames) grow(p.root_translation);
  for (std::size_t c = 0; c < player->ik_chain_count(); ++c) grow(player->ik_target(c));
  if (player->mode() == SkeletonMode::Warp && view_settings().side_by_side) {
    const Vec3 offset = original_offset(*player);
    for (const Vec3& e : ends) grow(e + offset);
  }
  return true;
}

std::string SkeletonView::caption_body(const SceneSpec& sc) const {
  const SkeletonSceneSpec& k = skeleton_scene(sc);
  const auto file = [](const std::string& f) {
    return std::filesystem::u8path(f).filename().u8string();
  };
  std::string what = file(k.amc);
  if (k.mode == SkeletonMode::Warp) {
    what +=
        " warped to " + (k.frames > 0 ? std::to_string(k.frames) : std::string("N")) + " frames";
    if (k.keyframe_in >= 0)
      what +=
          ", keyframe " + std::to_string(k.keyframe_in) + " -> " + std::to_string(k.keyframe_out);
  } else if (k.mode == SkeletonMode::Blend) {
    what += " blended into " + file(k.amc_b) + " (a " + std::to_string(k.a) + ", b " +
            std::to_string(k.b) + ", window " + std::to_string(k.window) + ")";
  }
  return "\nskeleton: " + file(k.asf) + ", " + what + ", scale " + format_number("%g", k.scale) +
         ", " + format_number("%g", k.fps) + " fps\n";
}

}  // namespace

const render::BodyView& body_view() {
  static const SkeletonView view;
  return view;
}

}  // namespace jelly::skeleton_view
