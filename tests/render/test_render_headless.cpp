// The course scene drawn through OSMesa: the pixels where the jelly, the floor, the hole and the
// bowl project (computed with the renderer's own camera) show the right thing. The PNGs are kept
// under ${JELLY_BINARY_DIR}/artifacts/render/ for CI.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <Eigen/Geometry>

#include "jelly/a1/task_table.hpp"
#include "jelly/cube_scene.hpp"
#include "jelly/movie/render_command.hpp"
#include "jelly/render/backend.hpp"
#include "jelly/render/captions.hpp"
#include "jelly/render/frame.hpp"
#include "jelly/scene.hpp"
#include "jelly/session/scene_catalog.hpp"
#include "jelly/session/simulation_run.hpp"
#include "offscreen.hpp"

namespace jelly::render {
namespace {

using namespace jelly::session;

namespace fs = std::filesystem;
const fs::path kArtifacts = fs::path(JELLY_BINARY_DIR) / "artifacts" / "render";
constexpr int kW = 1280, kH = 720;

enum class PixelClass { Jelly, Floor, Bowl, Other };

const char* name(PixelClass c) {
  switch (c) {
    case PixelClass::Jelly: return "jelly";
    case PixelClass::Floor: return "floor";
    case PixelClass::Bowl: return "bowl";
    default: return "other";
  }
}

/// Classifies a pixel by the hue the renderer gives each thing (renderer.hpp colors::*), with
/// room for shading: jelly is red, the floor light grey, the bowl blue.
PixelClass classify(const std::array<std::uint8_t, 4>& p) {
  const int r = p[0], g = p[1], b = p[2];
  if (r > 60 && r > 2 * g && r > b + 25) return PixelClass::Jelly;
  if (b > r + 30 && b > g + 10) return PixelClass::Bowl;
  if (r > 120 && std::abs(r - g) < 20 && std::abs(g - b) < 30) return PixelClass::Floor;
  return PixelClass::Other;
}

/// The class most pixels in a 5×5 block around the projection of x have.
PixelClass class_at(const Image& img, const OrbitCamera& cam, const Vec3& x) {
  const auto p = cam.project(x, img.width, img.height);
  if (!p) return PixelClass::Other;
  if (std::getenv("JELLY_RENDER_TEST_VERBOSE")) {
    const int px = static_cast<int>(std::lround(p->x())),
              py = static_cast<int>(std::lround(p->y()));
    if (px >= 0 && py >= 0 && px < img.width && py < img.height) {
      const auto c = img.at(px, py);
      std::printf("(%.2f, %.2f, %.2f) -> pixel (%d, %d) rgb %d %d %d: %s\n", x.x(), x.y(), x.z(),
                  px, py, c[0], c[1], c[2], name(classify(c)));
    }
  }
  int votes[4] = {0, 0, 0, 0};
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      const int px = static_cast<int>(std::lround(p->x())) + dx,
                py = static_cast<int>(std::lround(p->y())) + dy;
      if (px < 0 || py < 0 || px >= img.width || py >= img.height) continue;
      ++votes[static_cast<int>(classify(img.at(px, py)))];
    }
  int best = 3;
  for (int c = 0; c < 4; ++c)
    if (votes[c] > votes[best]) best = c;
  return static_cast<PixelClass>(best);
}

class HeadlessCourse : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(open_offscreen(kW, kH, backend_, renderer_));
    SceneResult scene = resolve_scene("course-2023", default_scenes_dir());
    ASSERT_TRUE(scene) << scene.error->text();
    run_ = std::make_unique<SimulationRun>(RunSetup::from_scene(*scene.scene), a1::task_table());
    ASSERT_TRUE(run_->ok()) << run_->error();
    ensure_drawables(*renderer_, {run_.get()});
    camera_.frame(drawable_of(*run_)->bounds(), static_cast<double>(kW) / kH);
  }
  void TearDown() override {
    run_.reset();  // draw proxies hold GL objects: before the context goes
    renderer_.reset();
  }

  Image render(const std::string& png, bool caption = false) {
    FrameOptions o;
    o.caption = caption;  // the printed parameters would cover part of the floor
    draw_frame(*renderer_, {run_.get()}, camera_, o, kW, kH);
    Image img = backend_->read_pixels();
    const std::string err = write_png(kArtifacts / png, img);
    EXPECT_TRUE(err.empty()) << err;
    return img;
  }

  Vec3 jelly_centre() const { return run_->simulator()->state().x.rowwise().mean(); }
  const Plane& floor() const {
    for (const Terrain& t : run_->simulator()->world().terrains())
      if (const auto* p = std::get_if<Plane>(&t.shape)) return *p;
    throw std::runtime_error("course scene without a floor");
  }
  const Bowl& bowl() const {
    for (const Terrain& t : run_->simulator()->world().terrains())
      if (const auto* b = std::get_if<Bowl>(&t.shape)) return *b;
    throw std::runtime_error("course scene without a bowl");
  }
  /// Horizontal unit vector across the view (to the camera's right).
  Vec3 across() const { return towards_camera().cross(Vec3::UnitY()).normalized(); }
  /// Horizontal unit vector from the scene towards the camera.
  Vec3 towards_camera() const {
    Vec3 d = camera_.eye() - camera_.target;
    d.y() = 0.0;
    return d.normalized();
  }

  std::unique_ptr<Backend> backend_;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<SimulationRun> run_;
  OrbitCamera camera_;
};

TEST_F(HeadlessCourse, AtStartJellyFloorHoleAndBowlAreWhereThePhysicsPutsThem) {
  EXPECT_EQ(backend_->name(), "offscreen");
  const Image img = render("course-t0.png");
  ASSERT_EQ(img.width, kW);
  const Plane& p = floor();
  const Vec3 toward = towards_camera();
  const double margin = 0.2;  // [m] either side of the hole's edge (6–10 px at this distance)

  EXPECT_EQ(class_at(img, camera_, jelly_centre()), PixelClass::Jelly);
  // 1.5 m above the cube's top is not jelly.
  const double half = 0.5 * cube_spec(run_->setup().scene).edge;
  EXPECT_NE(class_at(img, camera_, jelly_centre() + Vec3(0, half + 1.5, 0)), PixelClass::Jelly);
  // The hole's edge is drawn at its physical radius: just outside is floor, just inside we see
  // down into the bowl, on the near and on the far side.
  for (double side : {1.0, -1.0}) {
    const Vec3 out = p.hole_center + side * (p.hole_radius + margin) * toward;
    const Vec3 in = p.hole_center + side * (p.hole_radius - margin) * toward;
    EXPECT_EQ(class_at(img, camera_, out), PixelClass::Floor)
        << "side " << side << ": " << name(class_at(img, camera_, out));
    EXPECT_EQ(class_at(img, camera_, in), PixelClass::Bowl)
        << "side " << side << ": " << name(class_at(img, camera_, in));
  }
  // The bowl's bottom, seen through the hole.
  EXPECT_EQ(class_at(img, camera_, bowl().center - bowl().radius * Vec3::UnitY()),
            PixelClass::Bowl);
  // The hole's edge across the view, left and right.
  for (double side : {1.0, -1.0}) {
    EXPECT_EQ(class_at(img, camera_, p.hole_center + side * (p.hole_radius + margin) * across()),
              PixelClass::Floor);
    EXPECT_EQ(class_at(img, camera_, p.hole_center + side * (p.hole_radius - margin) * across()),
              PixelClass::Bowl);
  }
  // Floor farther out, 3 m beyond the hole to the side.
  EXPECT_EQ(class_at(img, camera_, p.hole_center + (p.hole_radius + 3.0) * across()),
            PixelClass::Floor);
}

TEST_F(HeadlessCourse, TheParametersArePrintedOnTheFrame) {
  const Image plain = render("course-t0-plain.png", false);
  const Image printed = render("course-t0.png", true);
  // The caption sits at the bottom-left: its rows differ, and hold light text on a dark panel.
  const std::string text = caption(run_->setup(), 0.0);
  const Eigen::Vector2i size = Renderer::text_size(text, text_scale(kH));
  int changed = 0, light = 0;
  for (int y = kH - size.y(); y < kH; ++y)
    for (int x = 0; x < std::min(kW, size.x()); ++x) {
      const auto a = plain.at(x, y), b = printed.at(x, y);
      changed += a != b;
      light += b[0] > 200 && b[1] > 200 && b[2] > 200 && b[2] > a[2] + 20;
    }
  EXPECT_GT(changed, size.x() * size.y() / 2);
  EXPECT_GT(light, 1000);  // the glyphs
}

TEST_F(HeadlessCourse, AfterLandingTheJellyIsInTheBowl) {
#if !JELLY_RENDER_WITH_SOLUTIONS
  GTEST_SKIP() << "needs the reference solution (solutions/) for the jelly to land";
#endif
  run_->advance_to(3.0);
  ASSERT_FALSE(run_->unstable()) << run_->simulator()->instability()->message();
  const Vec3 c = jelly_centre();
  // Landed: below its start, within the hole's circle (it tips into the bowl).
  EXPECT_LT(c.y(), 5.0);
  const Plane& p = floor();
  EXPECT_LT(std::hypot(c.x() - p.hole_center.x(), c.z() - p.hole_center.z()), p.hole_radius);
  const Image img = render("course-landed.png");
  EXPECT_EQ(class_at(img, camera_, c), PixelClass::Jelly);
  // Where it started is empty now (sky or far floor, not jelly).
  EXPECT_NE(class_at(img, camera_, cube_spec(run_->setup().scene).center), PixelClass::Jelly);
  EXPECT_EQ(class_at(img, camera_, p.hole_center + (p.hole_radius + 3.0) * across()),
            PixelClass::Floor);
}

TEST(RenderCommand, WritesNumberedFramesWithTheParametersPrinted) {
  const fs::path dir = kArtifacts / "command";
  fs::remove_all(dir);
  std::vector<std::string> args = {
      "render", "course-2023", "--frames", dir.string(), "--width", "480",       "--height",
      "270",    "--fps",       "10",       "--duration", "0.2",     "--no-video"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  ASSERT_EQ(movie::render_command(static_cast<int>(argv.size()), argv.data()), 0);
  for (const char* f : {"frame_00000.png", "frame_00001.png", "frame_00002.png"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  EXPECT_FALSE(fs::exists(dir / "frame_00003.png"));
}

// A kind without a view module (the particles) gives its caption line itself: the particles'
// count and mass, as the caption said when the renderer read them from the scene.
TEST(Captions, AKindWithoutAViewGivesItsOwnLine) {
  const SceneResult r =
      load_scene(fs::path(JELLY_SOURCE_DIR) / "scenes" / "two-particle-spring.toml");
  ASSERT_TRUE(r) << r.error->text();
  const std::string text = caption(session::RunSetup::from_scene(*r.scene), 0.0);
  EXPECT_NE(text.find("\nparticles: 2, m = 1 kg\n"), std::string::npos) << text;
}

TEST(RenderCommand, UsageErrorsReturnTwo) {
  std::vector<std::vector<std::string>> cases = {
      {"render"},                                                           // no scene
      {"render", "course-2023"},                                            // no --frames
      {"render", "course-2023", "--frames", "/tmp/x", "--bogus"},           // unknown option
      {"render", "course-2023", "--frames", "/tmp/x", "--compare", "rk4"},  // one integrator
      {"render", "course-2023", "--frames", "/tmp/x", "--width", "0"},
      {"render", "course-2023", "--frames", "/tmp/x", "--set", "no-equals-sign"},
      {"render", "course-2023", "--frames", "/tmp/x", "--replay", "a.csv", "--benchmark", "2"},
      {"render", "no-such-scene", "--frames", "/tmp/x"},
  };
  for (auto& args : cases) {
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    EXPECT_EQ(movie::render_command(static_cast<int>(argv.size()), argv.data()), 2) << args.back();
  }
}

}  // namespace
}  // namespace jelly::render
