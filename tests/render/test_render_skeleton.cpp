// The skeleton of assignment A3 in the viewer: its scenes build a World whose steps play the
// motion (the player), the playback controls change the shown frame, the warp's sliders re-warp
// through the tasks, a missing task is a message (never a crash), and through OSMesa the skeleton
// is drawn in its colours (the original beside a warp, the picked bone). The course's scenes, with
// the linked tasks (the reference's in a build with solutions). PNGs under
// ${JELLY_BINARY_DIR}/artifacts/render/.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>

#include "jelly/bodies/skeleton/view/skeleton_view.hpp"
#include "jelly/render/backend.hpp"
#include "jelly/render/captions.hpp"
#include "jelly/render/frame.hpp"
#include "jelly/render/image.hpp"
#include "jelly/session/assignments.hpp"
#include "jelly/session/scene_catalog.hpp"
#include "jelly/session/simulation_run.hpp"
#include "offscreen.hpp"
#include "skeleton_runs.hpp"

namespace jelly::render {
namespace {

namespace fs = std::filesystem;
using session::RunSetup;
using session::SimulationRun;
using skeleton_view::SkeletonDrawable;
const fs::path kArtifacts = fs::path(JELLY_BINARY_DIR) / "artifacts" / "render";
constexpr int kW = 960, kH = 540;

TEST(SkeletonView, AMissingTaskIsAMessageNotACrash) {
  const TaskTable none;  // no skeleton slot filled
  auto run = run_of("hw2-warp-2022", &none);
  ASSERT_TRUE(run && run->ok()) << (run ? run->error() : "");
  SkeletonPlayer& p = player_of(*run);
  EXPECT_NE(p.problem().find("forward_kinematics"), std::string::npos) << p.problem();
  EXPECT_NE(p.problem().find("time_map"), std::string::npos) << p.problem();
  EXPECT_EQ(p.frame_count(), 0);
  EXPECT_EQ(p.output_frames(0), nullptr);
  Renderer renderer(nullptr);
  auto d = renderer.make_drawable(run->simulator()->world());
  run->advance_to(0.1);
  renderer.draw(*d, run->simulator()->world(), OrbitCamera{}, DrawOptions{},
                Viewport{0, 0, 320, 240});
  const auto* skeleton = d->body<SkeletonDrawable>();
  ASSERT_NE(skeleton, nullptr);
  EXPECT_TRUE(skeleton->shown().bones().indices.empty());
  EXPECT_NE(skeleton->message().find("not drawn"), std::string::npos) << skeleton->message();
}

/// The setup of the course scene `name`, as a run starts from it.
RunSetup setup_of(const std::string& name) {
  SceneResult scene = session::resolve_scene(name, session::default_scenes_dir());
  EXPECT_TRUE(scene) << scene.error->text();
  return scene ? RunSetup::from_scene(*scene.scene) : RunSetup{};
}

TEST(SkeletonView, TheCaptionNamesNoIntegratorForAPlayedMotion) {
  const std::string played = caption(setup_of("hw2-fk-2022"), 0.5);
  EXPECT_EQ(played.rfind("hw2-fk-2022   t = 0.500 s", 0), 0u) << played;
  EXPECT_EQ(played.find("h = "), std::string::npos) << played;
  // A simulated scene (one made in code: a release of this assignment alone has no other kind's
  // scene file) still names its integrator and step.
  RunSetup cube;
  cube.scene.name = "made-in-code";
  const std::string simulated = caption(cube, 0.5);
  EXPECT_NE(simulated.find("   h = "), std::string::npos) << simulated;
}

#if JELLY_RENDER_WITH_SOLUTIONS

TEST(SkeletonControls, TheStepsPlayTheMotionAndTheControlsChangeTheFrame) {
  auto run = run_of("hw2-fk-2022");
  ASSERT_TRUE(run && run->ok()) << (run ? run->error() : "");
  SkeletonPlayer& p = player_of(*run);
  EXPECT_EQ(p.problem(), "");
  ASSERT_EQ(p.frame_count(), 148);
  run->advance_to(0.25);  // 0.25 s at 120 fps: frame 30 (within a step's 0.12 frames)
  EXPECT_NEAR(p.position(), 30.0, 0.2);
  p.set_speed(2.0);
  run->advance_to(0.35);
  EXPECT_NEAR(p.position(), 54.0, 0.3);
  p.step(+1);
  EXPECT_FALSE(p.playing());
  EXPECT_EQ(p.frame(), 55);
  p.step(-2);
  EXPECT_EQ(p.frame(), 53);
  run->advance_to(0.5);  // paused: the frame stays
  EXPECT_EQ(p.frame(), 53);
  p.seek(1000);
  EXPECT_EQ(p.frame(), 147);
  p.step(+1);  // wraps
  EXPECT_EQ(p.frame(), 0);
  p.seek(20);
  p.stop();
  EXPECT_EQ(p.frame(), 0);
  // The shown frame's bones are the motion's frame through forward kinematics: the root at T.
  p.seek(40);
  const skeleton::BoneFrames* f = p.output_frames(p.frame());
  ASSERT_NE(f, nullptr);
  EXPECT_EQ((f->start[0] - p.input().frames[40].root_translation).norm(), 0.0);
}

TEST(SkeletonControls, TheWarpSlidersReWarpThroughTheTasks) {
  auto run = run_of("hw2-warp-2022");
  ASSERT_TRUE(run && run->ok()) << (run ? run->error() : "");
  SkeletonPlayer& p = player_of(*run);
  ASSERT_EQ(p.frame_count(), 450);
  EXPECT_EQ(p.warp().keyframe_in, 160);
  skeleton::TimeWarp w = p.warp();
  w.output_frames = 300;
  w.keyframe_in = 100;
  w.keyframe_out = 200;
  p.seek(299);
  EXPECT_EQ(p.set_warp(w), "");
  EXPECT_EQ(p.frame_count(), 300);
  // Output K_out is input K_in (s(K_out) = K_in exactly, t = 0).
  EXPECT_EQ(p.output().frames[200].root_translation, p.input().frames[100].root_translation);
  EXPECT_EQ(p.frame(), 299);
  // A refused warp says why and changes nothing.
  w.keyframe_out = 299;
  EXPECT_NE(p.set_warp(w).find("K_out"), std::string::npos);
  EXPECT_EQ(p.frame_count(), 300);
  EXPECT_EQ(p.warp().keyframe_out, 200);
  EXPECT_EQ(p.set_warp(p.scene_warp()), "");
  EXPECT_EQ(p.output().frames[150].root_translation, p.input().frames[160].root_translation);
}

// ---------------------------------------------------------------------------------------------
// Pictures (OSMesa).

class HeadlessSkeleton : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(open_offscreen(kW, kH, backend_, renderer_)); }
  void TearDown() override {
    skeleton_view::view_settings() = {};
    run_.reset();
    renderer_.reset();
  }
  Image render(const std::string& scene, double t, const std::string& png) {
    run_ = run_of(scene);
    EXPECT_TRUE(run_ && run_->ok());
    run_->advance_to(t);
    std::vector<SimulationRun*> runs{run_.get()};
    ensure_drawables(*renderer_, runs);
    OrbitCamera cam;
    cam.frame(drawable_of(*run_)->bounds(), double(kW) / kH);
    FrameOptions fo;
    draw_frame(*renderer_, runs, cam, fo, kW, kH);
    Image img = backend_->read_pixels();
    EXPECT_EQ(write_png(kArtifacts / png, img), "");
    return img;
  }
  std::unique_ptr<Backend> backend_;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<SimulationRun> run_;
};

TEST_F(HeadlessSkeleton, EachCourseSceneDrawsItsBonesAndJoints) {
  for (const char* scene : {"hw2-fk-2022", "hw2-warp-2022", "hw2-blend-2022", "hw2-retime-2023"}) {
    const Image img = render(scene, 0.5, std::string("skeleton-") + scene + ".png");
    EXPECT_GT(pixels_of(img, skeleton_view::kBone), 150) << scene;
    EXPECT_GT(pixels_of(img, skeleton_view::kJoint), 30) << scene;
    EXPECT_EQ(pixels_of(img, skeleton_view::kPickedBone), 0) << scene;
  }
}

TEST_F(HeadlessSkeleton, AWarpShowsTheOriginalInItsColourAndThePickedBone) {
  skeleton_view::view_settings().picked_bone = 2;  // lfemur
  Image img = render("hw2-warp-2022", 1.0, "skeleton-warp-picked.png");
  EXPECT_GT(pixels_of(img, skeleton_view::kOriginalBone), 150);
  EXPECT_GT(pixels_of(img, skeleton_view::kPickedBone), 20);
  skeleton_view::view_settings() = {};
  skeleton_view::view_settings().show_original = false;
  img = render("hw2-warp-2022", 1.0, "skeleton-warp-alone.png");
  EXPECT_EQ(pixels_of(img, skeleton_view::kOriginalBone), 0);
  EXPECT_GT(pixels_of(img, skeleton_view::kBone), 150);
}

#endif  // JELLY_RENDER_WITH_SOLUTIONS

}  // namespace
}  // namespace jelly::render
