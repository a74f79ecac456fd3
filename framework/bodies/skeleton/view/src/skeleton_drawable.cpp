// A skeleton world drawn: the shown frame's figure from the player's forward kinematics, the
// original beside it in a warp, the picked bone; or nothing and the player's message.
#include <algorithm>

#include "jelly/bodies/skeleton/view/skeleton_view.hpp"

namespace jelly::skeleton_view {

namespace {
/// The GPU meshes, in this order.
enum Part {
  kBones,
  kJoints,
  kPicked,
  kOriginalBones,
  kOriginalJoints,
  kChain,
  kTargets,
  kEffectors,
  kParts
};
/// The ik marks' sizes: the target's ball, the reach of its three arms and the end effector's
/// ball as multiples of a joint's radius; the arms and a chain bone as multiples of a bone's. The
/// end effector's ball is the larger: on a reached target the arms stick out of it.
constexpr double kTargetFactor = 1.2, kArmFactor = 4.5, kEffectorFactor = 1.8;
constexpr double kArmRadiusFactor = 0.6, kChainFactor = 1.4;
}  // namespace

ViewSettings& view_settings() {
  static ViewSettings settings;
  return settings;
}

double figure_size(const SkeletonPlayer& player) {
  const skeleton::BoneFrames* f = player.input_frames(0);
  if (!f || f->end.empty()) return 1.0;
  Vec3 lo = f->end.front(), hi = lo;
  for (const Vec3& e : f->end) {
    lo = lo.cwiseMin(e);
    hi = hi.cwiseMax(e);
  }
  const double size = (hi - lo).maxCoeff();
  return size > 0.0 ? size : 1.0;
}

Vec3 original_offset(const SkeletonPlayer& player) {
  return Vec3(-0.8 * figure_size(player), 0.0, 0.0);
}

SkeletonDrawable::SkeletonDrawable(const World& world) {
  const SkeletonPlayer* player = find_skeleton_player(world);
  const double size = player ? figure_size(*player) : 1.0;
  shown_ = std::make_unique<SkeletonFigure>(size);
  original_ = std::make_unique<SkeletonFigure>(size);
}

std::string SkeletonDrawable::message() const { return message_; }

void SkeletonDrawable::update(const World& world, const render::DrawOptions&) {
  const SkeletonPlayer* player = find_skeleton_player(world);
  original_shown_ = false;
  if (!player) return;
  const ViewSettings& s = view_settings();
  const int frame = player->frame();
  const skeleton::BoneFrames* shown = player->output_frames(frame);
  shown_->update(shown ? *shown : skeleton::BoneFrames{}, Vec3::Zero(), shown ? s.picked_bone : -1);
  ik_.update(*player, shown ? *shown : skeleton::BoneFrames{}, *shown_, s.picked_bone);
  if (player->mode() == SkeletonMode::Warp && s.show_original && player->frame_count() > 0) {
    const Vec3 offset = s.side_by_side ? original_offset(*player) : Vec3::Zero();
    if (const skeleton::BoneFrames* f = player->input_frames(frame)) {
      original_->update(*f, offset, s.picked_bone);
      original_shown_ = true;
    }
  }
  message_ = player->problem().empty() ? "" : "skeleton not drawn: " + player->problem();
}

void IkMarks::update(const SkeletonPlayer& player, const skeleton::BoneFrames& f,
                     const SkeletonFigure& figure, int picked) {
  for (render::Mesh* m : {&chain, &targets, &effectors}) {
    m->positions.clear();
    m->normals.clear();
    m->indices.clear();
  }
  target_radius = kTargetFactor * figure.joint_radius();
  effector_radius = kEffectorFactor * figure.joint_radius();
  chain_radius = kChainFactor * figure.bone_radius();
  const double arm = kArmFactor * figure.joint_radius();
  for (std::size_t c = 0; c < player.ik_chain_count(); ++c) {
    const Vec3 t = player.ik_target(c);
    figure.add_sphere(targets, t, target_radius);
    for (int axis = 0; axis < 3; ++axis)
      figure.add_cylinder(targets, t - arm * Vec3::Unit(axis), t + arm * Vec3::Unit(axis),
                          kArmRadiusFactor * figure.bone_radius());
    if (f.end.empty()) continue;  // no forward kinematics: the balls alone
    const IkChainState& chain_state = player.ik_chain(c);
    for (int b : chain_state.bones)
      if (b != picked)
        figure.add_cylinder(chain, f.start[static_cast<std::size_t>(b)],
                            f.end[static_cast<std::size_t>(b)], chain_radius);
    figure.add_sphere(effectors, f.end[static_cast<std::size_t>(chain_state.end)], effector_radius);
  }
}

void SkeletonDrawable::create_gpu(const render::Gl& gl, GLuint /*particle_positions*/) {
  gl_ = &gl;
  gpu_.resize(kParts);
  for (render::GpuMesh& m : gpu_) m.create(gl, true, true);
}

void SkeletonDrawable::destroy_gpu(const render::Gl& gl) {
  for (render::GpuMesh& m : gpu_) m.destroy(gl);
  gpu_.clear();
  gl_ = nullptr;
}

void SkeletonDrawable::draw_surfaces(const render::SurfacePass& pass, const World&,
                                     const render::DrawOptions& options) {
  if (!options.surface || !gl_ || gpu_.size() != kParts) return;
  pass.set_int("u_plane", 0);
  pass.set_int("u_has_hole", 0);
  pass.set_material(kBoneMaterial);
  const auto draw = [&](const render::Mesh& mesh, Part part, const Eigen::Vector3f& color) {
    if (mesh.indices.empty()) return;
    pass.set_color("u_color", color);
    gpu_[part].upload_indices(*gl_, mesh.indices);  // the figure's triangles change with the pick
    pass.draw_streamed(mesh, gpu_[part], false);
  };
  draw(shown_->bones(), kBones, kBone);
  draw(shown_->joints(), kJoints, kJoint);
  draw(shown_->picked(), kPicked, kPickedBone);
  draw(ik_.chain, kChain, kChainBone);
  draw(ik_.targets, kTargets, kTarget);
  draw(ik_.effectors, kEffectors, kEffector);
  if (!original_shown_) return;
  draw(original_->bones(), kOriginalBones, kOriginalBone);
  draw(original_->joints(), kOriginalJoints, kJoint);
  draw(original_->picked(), kPicked, kPickedBone);
}

}  // namespace jelly::skeleton_view
