// A4's inverse kinematics in the viewer (issue 32, item 3): the player solves again only when a
// target, a chain or a setting changed, warm-started from the shown posture and through the same
// solve_ik as `jelly run` (restore goes back to the posture before that solve, contract §11.16); a
// task that answers wrongly is a message, never a crash; the mouse's drag puts the target under
// the mouse in the plane facing the camera; and through OSMesa the target, the chain and the end
// effector are drawn where the camera projects them. PNGs under
// ${JELLY_BINARY_DIR}/artifacts/render/.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "jelly/bodies/skeleton/view/ik_target.hpp"
#include "jelly/bodies/skeleton/view/skeleton_view.hpp"
#include "jelly/render/backend.hpp"
#include "jelly/render/frame.hpp"
#include "jelly/render/image.hpp"
#include "jelly/session/assignments.hpp"
#include "jelly/session/scene_catalog.hpp"
#include "jelly/session/simulation_run.hpp"
#include "jelly/skeleton_tasks.hpp"
#include "offscreen.hpp"
#include "skeleton_runs.hpp"

namespace jelly::render {
namespace {

namespace fs = std::filesystem;
using session::RunSetup;
using session::SimulationRun;
using skeleton_view::point_under_mouse;
using skeleton_view::SkeletonDrawable;
using skeleton_view::target_near;
const fs::path kArtifacts = fs::path(JELLY_BINARY_DIR) / "artifacts" / "render";
constexpr int kW = 960, kH = 540;

// ---- the drag, without GL --------------------------------------------------------------------

/// A camera looking at the course's ball from an angle, as a viewer would after orbiting.
OrbitCamera camera_at(const Vec3& target) {
  OrbitCamera cam;
  cam.target = target + Vec3(0.3, -0.5, 0.2);
  cam.yaw_degrees = 57.0;
  cam.pitch_degrees = 21.0;
  cam.distance = 9.0;
  return cam;
}

TEST(SkeletonIkDrag, TheTargetGoesUnderTheMouseInThePlaneFacingTheCamera) {
  const Vec3 ball(-0.0692501, 3.85358, -1.63441);
  const OrbitCamera cam = camera_at(ball);
  const Vec3 forward = skeleton_view::camera_axis(cam, 2);
  EXPECT_NEAR((cam.target - cam.eye()).normalized().dot(forward), 1.0, 1e-12);
  for (const Eigen::Vector2d& mouse : {Eigen::Vector2d(480, 270), Eigen::Vector2d(100, 500),
                                       Eigen::Vector2d(900, 30), Eigen::Vector2d(612.5, 301.25)}) {
    const std::optional<Vec3> at = point_under_mouse(cam, kW, kH, mouse, ball);
    ASSERT_TRUE(at) << mouse.transpose();
    // In the plane through the ball that faces the camera ...
    EXPECT_NEAR((*at - ball).dot(forward), 0.0, 1e-9) << mouse.transpose();
    // ... and drawn under the mouse (the projection is in float: a hundredth of a pixel).
    const std::optional<Eigen::Vector2d> drawn = cam.project(*at, kW, kH);
    ASSERT_TRUE(drawn);
    EXPECT_NEAR(drawn->x(), mouse.x(), 0.01) << mouse.transpose();
    EXPECT_NEAR(drawn->y(), mouse.y(), 0.01) << mouse.transpose();
  }
  // The mouse on the ball leaves it where it is.
  const Eigen::Vector2d on = *cam.project(ball, kW, kH);
  EXPECT_LT((*point_under_mouse(cam, kW, kH, on, ball) - ball).norm(), 1e-5);
  // Moving the mouse right moves the target along the camera's right, in the plane.
  const Vec3 right = *point_under_mouse(cam, kW, kH, on + Eigen::Vector2d(40, 0), ball) - ball;
  EXPECT_GT(right.normalized().dot(skeleton_view::camera_axis(cam, 0)), 0.999999);
}

TEST(SkeletonIkDrag, APressTakesTheNearestBallWithinItsRadius) {
  const Vec3 a(0, 3.8, -1.6), b(0.5, 3.8, -1.6);
  const OrbitCamera cam = camera_at(a);
  const Eigen::Vector2d pa = *cam.project(a, kW, kH), pb = *cam.project(b, kW, kH);
  EXPECT_EQ(target_near(cam, kW, kH, pa + Eigen::Vector2d(3, -2), {a, b}, 24.0), 0);
  EXPECT_EQ(target_near(cam, kW, kH, pb, {a, b}, 24.0), 1);
  EXPECT_EQ(target_near(cam, kW, kH, pa + Eigen::Vector2d(0, 60), {a, b}, 24.0), -1);
  EXPECT_EQ(target_near(cam, kW, kH, pa, {}, 24.0), -1);
}

// ---- the player's live solves ------------------------------------------------------------------

#if JELLY_RENDER_WITH_SOLUTIONS

const skeleton::Posture& shown(const SkeletonPlayer& p) {
  return p.output().frames[static_cast<std::size_t>(p.frame())];
}

TEST(SkeletonIk, TheSceneSolveIsShownWithItsErrorAtEachUpdate) {
  auto run = run_of("hw3-ik");
  ASSERT_TRUE(run && run->ok()) << (run ? run->error() : "");
  SkeletonPlayer& p = player_of(*run);
  EXPECT_EQ(p.problem(), "");
  ASSERT_EQ(p.ik_chain_count(), 1u);
  EXPECT_EQ(p.skeleton().bones[static_cast<std::size_t>(p.ik_chain(0).end)].name, "rfingers");
  EXPECT_EQ(p.ik_chain(0).bones.size(), 9u);  // lowerback -> rfingers (contract §7)
  const IkSolveRecord& r = p.ik_record(0);
  ASSERT_TRUE(r.solved) << r.error;
  EXPECT_EQ(r.result.updates, 73);  // the contract's reference (§8, §11.17)
  EXPECT_TRUE(r.result.stable);
  ASSERT_EQ(r.errors.size(), 74u);  // one end-effector evaluation per update, and the last
  EXPECT_NEAR(r.errors.front(), 1.75161, 1e-5);
  EXPECT_EQ(r.errors.back(), r.result.error);
  EXPECT_EQ((p.ik_target(0) - Vec3(-0.0692501, 3.85358, -1.63441)).norm(), 0.0);
  EXPECT_FALSE(p.ik_update());  // nothing changed: no solve
  EXPECT_EQ(p.ik_solve_count(), 0);
}

TEST(SkeletonIk, AMovedTargetIsSolvedOnceWarmStartedAndRestoredToThePostureBeforeIt) {
  auto run = run_of("hw3-ik");
  ASSERT_TRUE(run && run->ok());
  SkeletonPlayer& p = player_of(*run);
  const skeleton::Posture solved = shown(p);
  const Vec3 ball = p.ik_target(0);
  p.set_ik_target(0, ball + Vec3(0.02, -0.03, 0.01));
  EXPECT_TRUE(p.ik_update());
  EXPECT_FALSE(p.ik_update());  // an idle frame does no solve
  EXPECT_EQ(p.ik_solve_count(), 1);
  const IkSolveRecord& moved = p.ik_record(0);
  ASSERT_TRUE(moved.solved) << moved.error;
  EXPECT_TRUE(moved.result.stable);
  // Warm-started from the solved posture: fewer updates than the 73 from IK.amc's frame 0 (the
  // error shrinks by about 1 − step a update: 0.038 to 1e-3 in about 35).
  EXPECT_GT(moved.result.updates, 0);
  EXPECT_LT(moved.result.updates, 50);
  EXPECT_NEAR(moved.errors.front(), (Vec3(0.02, -0.03, 0.01)).norm(), 2e-3);
  EXPECT_NE(shown(p).angles, solved.angles);
  // Out of reach: unstable, and the posture goes back to the one before *this* solve (§11.16).
  const skeleton::Posture before = shown(p);
  p.set_ik_target(0, ball + Vec3(0.0, 40.0, 0.0));
  EXPECT_TRUE(p.ik_update());
  const IkSolveRecord& far = p.ik_record(0);
  ASSERT_TRUE(far.solved) << far.error;
  EXPECT_FALSE(far.result.stable);
  EXPECT_EQ(far.result.updates, 1000);
  EXPECT_EQ(shown(p).angles, before.angles);
  EXPECT_EQ(shown(p).root_translation, before.root_translation);
  // Reset: the scene's target and its solve from IK.amc's frame 0, bit for bit.
  p.ik_reset();
  EXPECT_EQ((p.ik_target(0) - ball).norm(), 0.0);
  EXPECT_EQ(p.ik_record(0).result.updates, 73);
  EXPECT_EQ(shown(p).angles, solved.angles);
}

TEST(SkeletonIk, TheSettingsAndTheBonesSolveAgain) {
  auto run = run_of("hw3-ik");
  ASSERT_TRUE(run && run->ok());
  SkeletonPlayer& p = player_of(*run);
  p.ik_reset();  // from IK.amc's frame 0 again, then with limits from there
  skeleton::IkSettings s = p.ik_settings();
  EXPECT_EQ(s.step, 0.1);
  s.limits = true;
  p.set_ik_settings(s);
  EXPECT_TRUE(p.ik_update());
  EXPECT_TRUE(p.ik_record(0).result.stable);
  // Another end bone: the left hand's chain, highlighted; the ball stays where it was.
  const Vec3 ball = p.ik_target(0);
  const int lowerback = *p.skeleton().find("lowerback"), lfingers = *p.skeleton().find("lfingers");
  p.set_ik_bones(0, lowerback, lfingers);
  EXPECT_EQ(p.ik_chain(0).chain_error, "");
  EXPECT_EQ(p.ik_chain(0).bones.front(), lfingers);
  EXPECT_EQ((p.ik_target(0) - ball).norm(), 0.0);
  EXPECT_TRUE(p.ik_update());
  EXPECT_TRUE(p.ik_record(0).solved) << p.ik_record(0).error;
  // A start bone not above the end bone: the chain runs to the root (contract §6.1).
  p.set_ik_bones(0, lfingers, lowerback);
  EXPECT_EQ(p.ik_chain(0).bones.back(), 0);
}

std::vector<int> empty_chain(const skeleton::Skeleton&, int, int) { return {}; }

TEST(SkeletonIk, ATaskThatAnswersWronglyIsAMessageNotACrash) {
  SceneResult scene = session::resolve_scene("hw3-ik", session::default_scenes_dir());
  ASSERT_TRUE(scene);
  TaskTable tasks = session::tasks_for(*scene.scene);
  skeleton_tasks(tasks).ik_chain = &empty_chain;  // as a stub's
  auto run = run_of("hw3-ik", &tasks);
  ASSERT_TRUE(run && run->ok()) << (run ? run->error() : "");
  SkeletonPlayer& p = player_of(*run);
  EXPECT_NE(p.problem().find("task ik_chain"), std::string::npos) << p.problem();
  EXPECT_NE(p.problem().find("returned an empty chain"), std::string::npos) << p.problem();
  ASSERT_EQ(p.ik_chain_count(), 1u);
  EXPECT_NE(p.ik_chain(0).chain_error.find("returned an empty chain"), std::string::npos);
  p.set_ik_target(0, p.ik_target(0) + Vec3(0.1, 0, 0));
  EXPECT_FALSE(p.ik_update());  // nothing to solve on: no crash
  p.ik_reset();
  EXPECT_NE(p.problem().find("returned an empty chain"), std::string::npos);
}

TEST(SkeletonIk, AScheduleShowsEachFramesTargetAndSolvesTheShownFrame) {
  auto run = run_of("ik-moving-target");
  ASSERT_TRUE(run && run->ok());
  SkeletonPlayer& p = player_of(*run);
  ASSERT_EQ(p.frame_count(), 61);
  p.seek(30);  // t = 1 s: the course's ball
  EXPECT_LT((p.ik_target(0) - Vec3(-0.0692501, 3.85358, -1.63441)).norm(), 1e-12);
  EXPECT_TRUE(p.ik_record(0).result.stable);
  const skeleton::Posture other = p.output().frames[40];
  p.set_ik_target(0, p.ik_target(0) + Vec3(0, 0.05, 0));
  EXPECT_FALSE(p.playing());
  EXPECT_TRUE(p.ik_update());
  EXPECT_EQ(p.output().frames[40].angles, other.angles);  // only the shown frame is solved
}

// ---- pictures (OSMesa)
// ---------------------------------------------------------------------------

class HeadlessSkeletonIk : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(open_offscreen(kW, kH, backend_, renderer_)); }
  void TearDown() override {
    run_.reset();
    renderer_.reset();
  }
  /// Draws the run (full frame, no caption band: one run), keeps the camera.
  Image render(const std::string& png) {
    std::vector<SimulationRun*> runs{run_.get()};
    ensure_drawables(*renderer_, runs);
    cam_.frame(drawable_of(*run_)->bounds(), double(kW) / kH);
    cam_.yaw_degrees = 60.0;  // the right arm towards the eye
    cam_.distance *= 1.3;     // the framing's sphere is cut at the edges: all of it in view
    draw_frame(*renderer_, runs, cam_, FrameOptions{}, kW, kH);
    Image img = backend_->read_pixels();
    EXPECT_EQ(write_png(kArtifacts / png, img), "");
    return img;
  }
  Eigen::Vector2d at(const Vec3& p) const { return *cam_.project(p, kW, kH); }
  std::unique_ptr<Backend> backend_;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<SimulationRun> run_;
  OrbitCamera cam_;
};

TEST_F(HeadlessSkeletonIk, TheTargetTheChainAndTheEndEffectorAreWhereTheCameraProjectsThem) {
  run_ = run_of("ik-unreachable");
  ASSERT_TRUE(run_ && run_->ok());
  const SkeletonPlayer& p = player_of(*run_);
  const Image img = render("skeleton-ik-unreachable.png");
  const skeleton::BoneFrames* f = p.output_frames(p.frame());
  ASSERT_NE(f, nullptr);
  const IkChainState& chain = p.ik_chain(0);
  // Apart: the target's arms around its projection, the end effector's ball on the hand.
  EXPECT_GT(pixels_of(img, skeleton_view::kTarget, at(p.ik_target(0)), 12.0), 20);
  EXPECT_GT(pixels_of(img, skeleton_view::kEffector,
                      at(f->end[static_cast<std::size_t>(chain.end)]), 6.0),
            10);
  // Each chain bone's middle is drawn in the chain's colour (a bone long enough to see).
  int seen = 0, long_bones = 0;
  for (int b : chain.bones) {
    const auto i = static_cast<std::size_t>(b);
    if ((at(f->start[i]) - at(f->end[i])).norm() < 12.0) continue;
    ++long_bones;
    seen += pixels_of(img, skeleton_view::kChainBone, at(0.5 * (f->start[i] + f->end[i])), 4.0) > 0;
  }
  EXPECT_GT(long_bones, 2);
  EXPECT_EQ(seen, long_bones);
  // A bone off the chain is not: the left femur.
  const auto lfemur = static_cast<std::size_t>(*p.skeleton().find("lfemur"));
  EXPECT_EQ(
      pixels_of(img, skeleton_view::kChainBone, at(0.5 * (f->start[lfemur] + f->end[lfemur])), 3.0),
      0);
}

TEST_F(HeadlessSkeletonIk, OnAReachedTargetTheArmsStickOutOfTheEndEffector) {
  run_ = run_of("hw3-ik");
  ASSERT_TRUE(run_ && run_->ok());
  const SkeletonPlayer& p = player_of(*run_);
  const Image img = render("skeleton-ik-hw3.png");
  const Eigen::Vector2d ball = at(p.ik_target(0));
  EXPECT_GT(pixels_of(img, skeleton_view::kEffector, ball, 5.0), 10);
  EXPECT_GT(pixels_of(img, skeleton_view::kTarget, ball, 14.0), 10);
}

TEST_F(HeadlessSkeletonIk, FourChainsFourTargets) {
  run_ = run_of("hw3-ik-2024");
  ASSERT_TRUE(run_ && run_->ok());
  const SkeletonPlayer& p = player_of(*run_);
  ASSERT_EQ(p.ik_chain_count(), 4u);
  const Image img = render("skeleton-ik-2024.png");
  for (std::size_t c = 0; c < 4; ++c)
    EXPECT_GT(pixels_of(img, skeleton_view::kTarget, at(p.ik_target(c)), 14.0), 5) << c;
}

#endif  // JELLY_RENDER_WITH_SOLUTIONS

}  // namespace
}  // namespace jelly::render
