// The skeleton's view module (a body kind's GL side, jelly/render/body_view.hpp): a skeleton scene
// drawn lit from its player's forward kinematics (jelly/skeleton_player.hpp), bones as capsules
// (a cylinder between the joints) and joints as spheres, on the ground the kind's build adds; in
// a warp the original motion beside the warped one in its own colour; the picked bone
// highlighted; in an ik scene each chain's bones, target ball and end effector. Its viewer controls
// (play, pause, stop, step, frame slider, speed; the warp's sliders; the bone picker and its plot)
// are skeleton_controls.hpp and the panel in jelly_skeleton_view_controls.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "jelly/render/body_view.hpp"
#include "jelly/render/meshes.hpp"
#include "jelly/skeleton_player.hpp"

namespace jelly::skeleton_view {

/// Colours (linear RGB, 0–1; the tests classify pixels with them): the played (or warped)
/// skeleton's bones and joints, the original motion's bones beside a warp, the picked bone.
inline const Eigen::Vector3f kBone{0.22f, 0.50f, 0.95f};
inline const Eigen::Vector3f kJoint{0.95f, 0.80f, 0.25f};
inline const Eigen::Vector3f kOriginalBone{0.90f, 0.30f, 0.28f};
inline const Eigen::Vector3f kPickedBone{0.25f, 0.88f, 0.35f};
/// An ik scene's: each chain's target (the ball), its bones, and its end effector (the end of the
/// end bone).
inline const Eigen::Vector3f kTarget{0.92f, 0.22f, 0.78f};
inline const Eigen::Vector3f kChainBone{0.15f, 0.82f, 0.85f};
inline const Eigen::Vector3f kEffector{1.0f, 0.55f, 0.05f};
inline constexpr render::Material kBoneMaterial{0.35f, 32.0f};

/// What the view shows besides the played motion (the Skeleton panel edits it; one for the
/// program, read by every skeleton drawable each frame).
struct ViewSettings {
  bool show_original = true;  ///< in a warp: the original motion too
  bool side_by_side = true;   ///< the original beside the warped one (else overlaid)
  int picked_bone = -1;       ///< highlighted bone (−1: none)
};
ViewSettings& view_settings();

/// How far the original stands beside the warped skeleton [scene units]: along −x, by the
/// figure's size.
Vec3 original_offset(const SkeletonPlayer& player);
/// The size of the figure (the largest extent of the input's first frame; 1 without forward
/// kinematics).
double figure_size(const SkeletonPlayer& player);

/// One skeleton posture as meshes: the bones (a cylinder from each bone's start to its end, the
/// root has none), the joints (a sphere at each bone's end and at the root), and the picked bone
/// (its cylinder, thicker). Radii scale with the figure.
class SkeletonFigure {
 public:
  /// `size`: the figure's size (figure_size); `segments` around each cylinder and sphere.
  explicit SkeletonFigure(double size, int segments = 12);
  /// The meshes of `frames` moved by `offset`, with bone `picked` (−1: none) apart.
  void update(const skeleton::BoneFrames& frames, const Vec3& offset, int picked);
  const render::Mesh& bones() const { return bones_; }
  const render::Mesh& joints() const { return joints_; }
  const render::Mesh& picked() const { return picked_; }
  double bone_radius() const { return bone_radius_; }
  double joint_radius() const { return joint_radius_; }
  /// A cylinder of `radius` from a to b (open ends), and a sphere, added to `mesh`.
  void add_cylinder(render::Mesh& mesh, const Vec3& a, const Vec3& b, double radius) const;
  void add_sphere(render::Mesh& mesh, const Vec3& center, double radius) const;

 private:
  int segments_;
  double bone_radius_, joint_radius_;
  std::vector<Eigen::Vector3f> sphere_dirs_;
  std::vector<std::uint32_t> sphere_indices_;
  render::Mesh bones_, joints_, picked_;
};

/// An ik scene's marks over the figure: each chain's bones (thicker), its target (a small ball
/// with three arms along the axes) and its end effector's ball (larger than the target's: on a
/// reached target the arms stick out of it).
struct IkMarks {
  render::Mesh chain, targets, effectors;
  /// Radii [scene units]: the target's ball, the end effector's ball, a chain bone.
  double target_radius = 0.0, effector_radius = 0.0, chain_radius = 0.0;
  /// The marks of `player`'s chains at the shown frame (`frames`: its forward kinematics); the
  /// picked bone keeps its own highlight.
  void update(const SkeletonPlayer& player, const skeleton::BoneFrames& frames,
              const SkeletonFigure& figure, int picked);
};

/// The draw proxies of a skeleton world: the shown frame's figure and, in a warp, the original's;
/// in an ik scene the chains, targets and end effectors.
class SkeletonDrawable : public render::BodyDrawable {
 public:
  explicit SkeletonDrawable(const World& world);
  /// The figure of the shown frame (empty meshes when the tasks cannot give it).
  const SkeletonFigure& shown() const { return *shown_; }
  const SkeletonFigure& original() const { return *original_; }
  const IkMarks& ik_marks() const { return ik_; }
  /// Whether the last update drew the original too.
  bool original_shown() const { return original_shown_; }
  /// Why the skeleton is not (fully) drawn: the player's problem(), "" when all is well.
  std::string message() const override;

  void update(const World& world, const render::DrawOptions& options) override;
  void create_gpu(const render::Gl& gl, GLuint particle_positions) override;
  void destroy_gpu(const render::Gl& gl) override;
  void draw_surfaces(const render::SurfacePass& pass, const World& world,
                     const render::DrawOptions& options) override;

 private:
  std::unique_ptr<SkeletonFigure> shown_, original_;
  IkMarks ik_;
  bool original_shown_ = false;
  std::string message_;
  const render::Gl* gl_ = nullptr;    // from create_gpu
  std::vector<render::GpuMesh> gpu_;  // shown bones, joints, picked; original's; ik marks
};

/// The registered view of the skeleton kind.
const render::BodyView& body_view();
/// Its live controls in jelly-lab (the Skeleton panel section, keys): library
/// jelly_skeleton_view_controls, which only jelly-lab links.
std::unique_ptr<render::BodyControls> make_controls();

}  // namespace jelly::skeleton_view
