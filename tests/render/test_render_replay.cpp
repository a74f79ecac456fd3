// `jelly render --replay`: recorded positions drawn where they were recorded — not where the scene
// puts the cube, and without simulating. (The CSV reader itself:
// tests/session/test_replay_csv.cpp.)
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <stb_image.h>

#include "jelly/a1/task_table.hpp"
#include "jelly/movie/render_command.hpp"
#include "jelly/render/backend.hpp"
#include "jelly/render/frame.hpp"
#include "jelly/session/replay.hpp"
#include "jelly/session/scene_catalog.hpp"
#include "jelly/task_table.hpp"

namespace jelly::render {
namespace {

using namespace jelly::session;

namespace fs = std::filesystem;
const fs::path kArtifacts = fs::path(JELLY_BINARY_DIR) / "artifacts" / "render" / "replay";

/// An RGBA PNG read back (stb_image from libstb, the library write_png uses).
Image read_png(const fs::path& p) {
  int w = 0, h = 0, n = 0;
  unsigned char* data = stbi_load(p.string().c_str(), &w, &h, &n, 4);
  Image img;
  if (!data) return img;
  img.width = w;
  img.height = h;
  img.rgba.assign(data, data + static_cast<std::size_t>(w) * h * 4);
  stbi_image_free(data);
  return img;
}

/// Jelly pixels are red (renderer.hpp colors::jelly), as in test_render_headless.cpp.
bool jelly_pixel(const std::array<std::uint8_t, 4>& p) {
  return p[0] > 60 && p[0] > 2 * p[1] && p[0] > p[2] + 25;
}

/// Jelly pixels in a 7×7 block around the projection of x.
int jelly_votes(const Image& img, const OrbitCamera& cam, const Vec3& x) {
  const auto p = cam.project(x, img.width, img.height);
  if (!p) return 0;
  int votes = 0;
  for (int dy = -3; dy <= 3; ++dy)
    for (int dx = -3; dx <= 3; ++dx) {
      const int px = static_cast<int>(std::lround(p->x())) + dx,
                py = static_cast<int>(std::lround(p->y())) + dy;
      if (px >= 0 && py >= 0 && px < img.width && py < img.height)
        votes += jelly_pixel(img.at(px, py));
    }
  return votes;
}

int run_render(std::vector<std::string> args) {
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  return movie::render_command(static_cast<int>(argv.size()), argv.data());
}

TEST(RenderReplay, DrawsTheRecordedPositionsNotTheScenesStart) {
  constexpr int kW = 480, kH = 360;
  // The scene's world, its start and the camera the command frames it with.
  const SceneResult scene = resolve_scene("builtin:course-2023", default_scenes_dir());
  ASSERT_TRUE(scene) << scene.error->text();
  BackendOptions bo;
  bo.name = "offscreen";
  bo.width = kW;
  bo.height = kH;
  auto created = create_backend(bo);
  ASSERT_TRUE(created.backend) << created.error;
  OrbitCamera camera;
  Vec3Array start;
  {
    Renderer renderer(created.backend->gl(), 0);
    const std::unique_ptr<World> world = build_world(*scene.scene, a1::task_table());
    start = world->state().x;
    camera.frame(renderer.make_drawable(*world)->bounds(), static_cast<double>(kW) / kH);
  }
  created.backend.reset();
  // Two recorded frames: the cube moved 6 m along +x, then down into the bowl region.
  const Vec3 c0 = start.rowwise().mean();
  const Vec3 shift_a(6.0, -4.0, 0.0), shift_b(9.0, -7.0, 1.0);
  fs::create_directories(kArtifacts);
  const fs::path csv = kArtifacts / "moved.csv";
  {
    std::ofstream out(csv);
    out << "frame,time,particle,x,y,z\n";
    int f = 0;
    for (const Vec3& shift : {shift_a, shift_b}) {
      for (Eigen::Index i = 0; i < start.cols(); ++i) {
        const Vec3 x = start.col(i) + shift;
        out << f << "," << 1.5 * (f + 1) << "," << i << "," << x.x() << "," << x.y() << "," << x.z()
            << "\n";
      }
      ++f;
    }
  }
  const fs::path dir = kArtifacts / "frames";
  fs::remove_all(dir);
  ASSERT_EQ(run_render({"render", "builtin:course-2023", "--replay", csv.string(), "--frames",
                        dir.string(), "--width", std::to_string(kW), "--height", std::to_string(kH),
                        "--samples", "0", "--no-caption", "--label", "yours"}),
            0);
  const Image a = read_png(dir / "frame_00000.png"), b = read_png(dir / "frame_00001.png");
  ASSERT_EQ(a.width, kW);
  ASSERT_EQ(b.height, kH);
  EXPECT_FALSE(fs::exists(dir / "frame_00002.png"));
  EXPECT_GT(jelly_votes(a, camera, c0 + shift_a), 40);
  EXPECT_EQ(jelly_votes(a, camera, c0), 0)
      << "the cube is drawn where the scene starts it, not where recorded";
  EXPECT_GT(jelly_votes(b, camera, c0 + shift_b), 40);
  EXPECT_EQ(jelly_votes(b, camera, c0 + shift_a), 0);
}

TEST(RenderReplay, InputErrorsReturnTwoAndNameTheProblem) {
  const fs::path csv = kArtifacts / "three-particles.csv";
  fs::create_directories(kArtifacts);
  std::ofstream(csv) << "frame,time,particle,x,y,z\n0,0,0,0,0,0\n0,0,1,0,0,0\n0,0,2,0,0,0\n";
  const fs::path dir = kArtifacts / "unused";
  // Particle count against the scene's cube (1000).
  EXPECT_EQ(run_render({"render", "builtin:course-2023", "--replay", csv.string(), "--frames",
                        dir.string(), "--width", "64", "--height", "48"}),
            2);
  // Missing file, and options that mean simulating.
  EXPECT_EQ(run_render({"render", "builtin:course-2023", "--replay", "/no/such.csv", "--frames",
                        dir.string()}),
            2);
  EXPECT_EQ(run_render({"render", "builtin:course-2023", "--replay", csv.string(), "--frames",
                        dir.string(), "--compare", "rk4,midpoint"}),
            2);
  EXPECT_FALSE(fs::exists(dir / "frame_00000.png"));
}

// --camera is checked the same way when replaying and when simulating: a bad value is exit 2 and
// no frame.
TEST(RenderReplay, BadCameraIsAnInputErrorInBothModes) {
  const SceneResult scene = resolve_scene("builtin:course-2023", default_scenes_dir());
  ASSERT_TRUE(scene) << scene.error->text();
  const Vec3Array start = build_world(*scene.scene, a1::task_table())->state().x;
  fs::create_directories(kArtifacts);
  const fs::path csv = kArtifacts / "start.csv";
  {
    std::ofstream out(csv);
    out << "frame,time,particle,x,y,z\n";
    for (Eigen::Index i = 0; i < start.cols(); ++i)
      out << "0,0," << i << "," << start(0, i) << "," << start(1, i) << "," << start(2, i) << "\n";
  }
  const fs::path dir = kArtifacts / "bad-camera";
  fs::remove_all(dir);
  for (const char* camera : {"30,20", "30,20,-1", "a,b,c"}) {
    EXPECT_EQ(run_render({"render", "builtin:course-2023", "--replay", csv.string(), "--frames",
                          dir.string(), "--width", "64", "--height", "48", "--camera", camera}),
              2)
        << camera;
    EXPECT_EQ(
        run_render({"render", "builtin:course-2023", "--frames", dir.string(), "--duration", "0",
                    "--width", "64", "--height", "48", "--no-video", "--camera", camera}),
        2)
        << camera;
  }
  EXPECT_FALSE(fs::exists(dir / "frame_00000.png"));
  // A good value goes through in both modes.
  EXPECT_EQ(run_render({"render", "builtin:course-2023", "--replay", csv.string(), "--frames",
                        dir.string(), "--width", "64", "--height", "48", "--samples", "0",
                        "--camera", "30,20,25"}),
            0);
  EXPECT_EQ(run_render({"render", "builtin:course-2023", "--frames", dir.string(), "--duration",
                        "0", "--width", "64", "--height", "48", "--samples", "0", "--no-video",
                        "--camera", "30,20,25"}),
            0);
}

}  // namespace
}  // namespace jelly::render
