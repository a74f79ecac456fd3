// The cloth of assignment A2 drawn: its grid as a two-sided surface (front and back tinted apart),
// the pinned particles marked, the spring types as lines, the spheres (dynamic and kinematic in
// their own colours); and comparison mode, whose labels and caption cover no view. Worlds are
// built in code; the comparison frames use the scenes. PNGs under
// ${JELLY_BINARY_DIR}/artifacts/render/.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <stb_image.h>
#include <Eigen/Geometry>

#include "jelly/a2/task_table.hpp"
#include "jelly/bodies/cloth/view/cloth_view.hpp"
#include "jelly/cloth_physics.hpp"
#include "jelly/movie/render_command.hpp"
#include "jelly/render/backend.hpp"
#include "jelly/render/frame.hpp"
#include "jelly/render/meshes.hpp"
#include "jelly/session/assignments.hpp"
#include "jelly/session/scene_catalog.hpp"
#include "jelly/session/simulation_run.hpp"
#include "offscreen.hpp"

namespace jelly::render {
namespace {

namespace fs = std::filesystem;
using session::RunSetup;
using session::SimulationRun;
const fs::path kArtifacts = fs::path(JELLY_BINARY_DIR) / "artifacts" / "render";
constexpr int kW = 1280, kH = 720;

// ---------------------------------------------------------------------------------------------
// Worlds built in code: the course's two cloths (cloth contract §6).

/// 2022: a 25×25 cloth at y = 0 pinned at its corners, four dynamic spheres r = 0.5 above it.
std::unique_ptr<World> cloth_2022() {
  auto w = std::make_unique<World>(a2::task_table());
  ClothSpec c;  // n 25, L 4, m 1, corners pinned
  cloth_physics(*w).add_cloth(c);
  for (SpringType t : {SpringType::Structural, SpringType::Shear, SpringType::Bending})
    cloth_physics(*w).build_cloth_springs(0, t, 25000.0, 750.0);
  for (double x : {-0.75, 0.75})
    for (double z : {-0.75, 0.75}) {
      SphereSpec s;
      s.center = Vec3(x, 1.0, z);
      s.radius = 0.5;
      cloth_physics(*w).add_sphere(s);
    }
  w->set_gravity(Vec3(0.0, -9.8, 0.0));
  return w;
}

/// 2024: the cloth at y = 1 over one kinematic sphere r = 1 at the origin.
std::unique_ptr<World> cloth_2024() {
  auto w = std::make_unique<World>(a2::task_table());
  ClothSpec c;
  c.center = Vec3(0.0, 1.0, 0.0);
  cloth_physics(*w).add_cloth(c);
  cloth_physics(*w).build_cloth_springs(0, SpringType::Structural, 20000.0, 750.0);
  SphereSpec s;
  s.kinematic = true;
  s.radius = 1.0;
  cloth_physics(*w).add_sphere(s);
  return w;
}

// ---------------------------------------------------------------------------------------------
// Geometry (no GL).

TEST(ClothMeshes, OneVertexPerParticleTwoTrianglesPerCellFrontFacingUp) {
  constexpr int n = 4, first = 3;
  cloth_view::ClothSurface surface(n, first);
  const Mesh& m = surface.mesh();
  EXPECT_EQ(m.positions.size(), std::size_t(n * n));
  EXPECT_EQ(m.indices.size(), std::size_t(2 * 3 * (n - 1) * (n - 1)));
  // A flat grid as ClothGrid lays it out (i along x, k along z), after `first` other columns.
  Vec3Array x = Vec3Array::Constant(3, first + n * n, 99.0);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) x.col(first + i * n + k) = Vec3(0.5 * i, 2.0, 0.5 * k);
  surface.update(x);
  for (int v = 0; v < n * n; ++v) {
    EXPECT_EQ(m.positions[v], x.col(first + v).cast<float>()) << v;
    EXPECT_NEAR((m.normals[v] - Eigen::Vector3f::UnitY()).norm(), 0.0f, 1e-6f) << v;
  }
  // Every triangle winds counter-clockwise seen from +y (the front side).
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const auto& a = m.positions[m.indices[t]];
    const Eigen::Vector3f nrm =
        (m.positions[m.indices[t + 1]] - a).cross(m.positions[m.indices[t + 2]] - a);
    EXPECT_GT(nrm.y(), 0.0f) << "triangle " << t / 3;
  }
  // Fold the cloth: the normals follow (recomputed every update).
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) x.col(first + i * n + k) = Vec3(0.0, 2.0 - 0.5 * i, 0.5 * k);
  surface.update(x);
  for (int v = 0; v < n * n; ++v)
    EXPECT_NEAR(std::abs(m.normals[v].x()), 1.0f, 1e-5f) << "a vertical cloth's normal is ±x";
}

TEST(ClothMeshes, DrawablesFollowTheClothAndTheSpheres) {
  Renderer renderer(nullptr);
  auto w = cloth_2022();
  auto d = renderer.make_drawable(*w);
  ASSERT_EQ(d->bodies().size(), 1u);  // the cloth's only: no cube
  const auto* cloth = d->body<cloth_view::ClothDrawable>();
  ASSERT_NE(cloth, nullptr);
  ASSERT_EQ(cloth->cloth_surfaces().size(), 1u);
  ASSERT_EQ(cloth->spheres().size(), 4u);
  // The framing holds the cloth and the spheres above it.
  EXPECT_LE(d->bounds().lo.x(), -2.0);
  EXPECT_GE(d->bounds().hi.x(), 2.0);
  EXPECT_GE(d->bounds().hi.y(), 1.5);
  OrbitCamera cam;
  renderer.draw(*d, *w, cam, DrawOptions{}, Viewport{0, 0, 640, 360});
  for (int i = 0; i < 4; ++i) {
    const SphereBody s = cloth_physics(*w).sphere(i);
    for (const auto& p : cloth->spheres()[static_cast<std::size_t>(i)].mesh().positions)
      EXPECT_NEAR((p.cast<double>() - s.center).norm(), s.radius, 1e-5);
  }
  const ClothGrid& grid = cloth_physics(*w).cloths().front();
  EXPECT_EQ(cloth->cloth_surfaces()[0].mesh().positions[7], grid.position(0, 7).cast<float>());
}

// ---------------------------------------------------------------------------------------------
// Pictures (OSMesa).

enum class Hue {
  ClothFront,
  ClothBack,
  Pin,
  Dynamic,
  Kinematic,
  Structural,
  Shear,
  Bending,
  Sky,
  Other
};

const char* name(Hue h) {
  static const char* names[] = {"cloth front", "cloth back", "pin",   "dynamic sphere",
                                "kinematic",   "structural", "shear", "bending",
                                "sky",         "other"};
  return names[static_cast<int>(h)];
}

/// The nearest of the renderer's colours by chromaticity (shading scales a colour; the ambient
/// light and highlights shift it a little), after the shader's gamma.
Hue classify(const std::array<std::uint8_t, 4>& p) {
  const double sum = double(p[0]) + p[1] + p[2];
  if (sum < 45.0) return Hue::Other;
  const Eigen::Vector3d c = Eigen::Vector3d(p[0], p[1], p[2]) / sum;
  const std::array<std::pair<Hue, Eigen::Vector3f>, 10> refs = {{
      {Hue::ClothFront, cloth_view::kClothFront},
      {Hue::ClothBack, cloth_view::kClothBack},
      {Hue::Pin, cloth_view::kPin},
      {Hue::Dynamic, cloth_view::kDynamicSphere},
      {Hue::Kinematic, cloth_view::kKinematicSphere},
      {Hue::Structural, colors::kSprings[0]},
      {Hue::Shear, colors::kSprings[1]},
      {Hue::Bending, colors::kSprings[3]},
  }};
  // The sky's gradient (drawn without the lit shader's gamma): its two ends and its middle.
  const std::array<Eigen::Vector3f, 3> sky = {colors::kSkyTop, colors::kSkyHorizon,
                                              0.5f * (colors::kSkyTop + colors::kSkyHorizon)};
  Hue best = Hue::Other;
  double best_d = 0.06;  // farther than this from every colour: something else
  for (const auto& [hue, ref] : refs) {
    const Eigen::Vector3d g(std::pow(ref.x(), 1 / 1.1), std::pow(ref.y(), 1 / 1.1),
                            std::pow(ref.z(), 1 / 1.1));
    const double d = (c - g / g.sum()).norm();
    if (d < best_d) {
      best_d = d;
      best = hue;
    }
  }
  for (const Eigen::Vector3f& ref : sky) {
    const Eigen::Vector3d g = ref.cast<double>();
    const double d = (c - g / g.sum()).norm();
    if (d < best_d) {
      best_d = d;
      best = Hue::Sky;
    }
  }
  return best;
}

/// The hue most pixels of the 5×5 block around the projection of x have.
Hue hue_at(const Image& img, const OrbitCamera& cam, const Vec3& x) {
  const auto p = cam.project(x, img.width, img.height);
  if (!p) return Hue::Other;
  int votes[10] = {};
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      const int px = static_cast<int>(std::lround(p->x())) + dx,
                py = static_cast<int>(std::lround(p->y())) + dy;
      if (px >= 0 && py >= 0 && px < img.width && py < img.height)
        ++votes[static_cast<int>(classify(img.at(px, py)))];
    }
  int best = static_cast<int>(Hue::Other);
  for (int h = 0; h < 10; ++h)
    if (votes[h] > votes[best]) best = h;
  return static_cast<Hue>(best);
}

/// For failure messages: where x lands and the colour there.
std::string pixel_at(const Image& img, const OrbitCamera& cam, const Vec3& x) {
  const auto p = cam.project(x, img.width, img.height);
  if (!p) return "behind the camera";
  const int px = static_cast<int>(std::lround(p->x())), py = static_cast<int>(std::lround(p->y()));
  if (px < 0 || py < 0 || px >= img.width || py >= img.height) return "outside the frame";
  const auto c = img.at(px, py);
  return "pixel (" + std::to_string(px) + ", " + std::to_string(py) + ") rgb " +
         std::to_string(c[0]) + " " + std::to_string(c[1]) + " " + std::to_string(c[2]) + ": " +
         name(classify(c));
}

int count_hue(const Image& img, Hue hue) {
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) n += classify(img.at(x, y)) == hue;
  return n;
}

/// Whether the segment from p to the eye passes through one of the world's spheres.
bool hidden_by_a_sphere(const World& w, const Vec3& p, const Vec3& eye, double margin = 0.03) {
  const Vec3 d = eye - p;
  for (int i = 0; i < cloth_physics(w).sphere_count(); ++i) {
    const SphereBody s = cloth_physics(w).sphere(i);
    const double t = std::clamp((s.center - p).dot(d) / d.squaredNorm(), 0.0, 1.0);
    if ((p + t * d - s.center).norm() < s.radius + margin) return true;
  }
  return false;
}

class HeadlessCloth : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(open_offscreen(kW, kH, backend_, renderer_)); }
  void TearDown() override {
    drawable_.reset();
    renderer_.reset();
  }
  void use(std::unique_ptr<World> w) {
    world_ = std::move(w);
    drawable_ = renderer_->make_drawable(*world_);
    camera_ = OrbitCamera{};
    camera_.frame(drawable_->bounds(), double(kW) / kH);
  }
  Image render(const std::string& png, const DrawOptions& o = {}) {
    renderer_->begin_frame(kW, kH);
    renderer_->draw(*drawable_, *world_, camera_, o, Viewport{0, 0, kW, kH});
    renderer_->end_frame();
    Image img = backend_->read_pixels();
    const std::string err = write_png(kArtifacts / png, img);
    EXPECT_TRUE(err.empty()) << err;
    return img;
  }
  /// Cloth points away from the pins, every third of the grid, that no sphere hides.
  std::vector<Vec3> visible_cloth_points() const {
    std::vector<Vec3> out;
    const ClothGrid& g = cloth_physics(*world_).cloths().front();
    for (int i = 2; i < g.n() - 2; i += 3)
      for (int k = 2; k < g.n() - 2; k += 3) {
        const Vec3 p = world_->state().x.col(g.index(i, k));
        if (!hidden_by_a_sphere(*world_, p, camera_.eye())) out.push_back(p);
      }
    return out;
  }
  void expect_cloth(const Image& img, Hue side) {
    const std::vector<Vec3> points = visible_cloth_points();
    ASSERT_GE(points.size(), 20u);
    int hits = 0;
    for (const Vec3& p : points) {
      const Hue h = hue_at(img, camera_, p);
      hits += h == side;
      if (h != side)
        ADD_FAILURE() << "(" << p.transpose() << "): " << name(h) << ", expected " << name(side)
                      << "; " << pixel_at(img, camera_, p);
    }
    EXPECT_EQ(hits, static_cast<int>(points.size()));
  }

  std::unique_ptr<Backend> backend_;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<World> world_;
  std::unique_ptr<SceneDrawable> drawable_;
  OrbitCamera camera_;
};

TEST_F(HeadlessCloth, FrontFromAboveBackFromBelowAndTheSpheres) {
  use(cloth_2022());
  const Image above = render("cloth-2022-above.png");
  expect_cloth(above, Hue::ClothFront);
  // The four dynamic spheres: the point of each nearest the camera.
  for (int i = 0; i < 4; ++i) {
    const SphereBody s = cloth_physics(*world_).sphere(i);
    const Vec3 near = s.center + s.radius * 0.9 * (camera_.eye() - s.center).normalized();
    EXPECT_EQ(hue_at(above, camera_, near), Hue::Dynamic)
        << "sphere " << i << ": " << pixel_at(above, camera_, near);
  }
  // The top of the frame, above everything, is sky.
  EXPECT_EQ(classify(above.at(kW / 2, 4)), Hue::Sky);
  EXPECT_EQ(classify(above.at(4, 4)), Hue::Sky);

  camera_.pitch_degrees = -35.0;
  const Image below = render("cloth-2022-below.png");
  expect_cloth(below, Hue::ClothBack);
}

TEST_F(HeadlessCloth, PinnedCornersAreMarkedAndAFreedOneIsNot) {
  use(cloth_2022());
  const ClothGrid& g = cloth_physics(*world_).cloths().front();
  const std::array<int, 4> corners = {g.index(0, 0), g.index(0, g.n() - 1), g.index(g.n() - 1, 0),
                                      g.index(g.n() - 1, g.n() - 1)};
  const Image pinned = render("cloth-pins.png");
  std::vector<int> visible;  // the corners no sphere hides (three of four from this camera)
  for (int p : corners) {
    if (hidden_by_a_sphere(*world_, world_->state().x.col(p), camera_.eye())) continue;
    visible.push_back(p);
    EXPECT_EQ(hue_at(pinned, camera_, world_->state().x.col(p)), Hue::Pin) << "particle " << p;
  }
  ASSERT_GE(visible.size(), 2u);
  cloth_physics(*world_).set_pinned(visible[0], false);
  const Image freed = render("cloth-pin-freed.png");
  EXPECT_NE(hue_at(freed, camera_, world_->state().x.col(visible[0])), Hue::Pin);
  EXPECT_EQ(hue_at(freed, camera_, world_->state().x.col(visible[1])), Hue::Pin);
  DrawOptions no_pins;
  no_pins.markers = false;
  EXPECT_EQ(count_hue(render("cloth-no-pins.png", no_pins), Hue::Pin), 0);
  EXPECT_GT(count_hue(pinned, Hue::Pin), 3 * 40);  // three or four dots of ≥ 40 px
}

TEST_F(HeadlessCloth, EachSpringTypeIsDrawnInItsColourWhenToggled) {
  use(cloth_2022());
  DrawOptions lines;
  lines.surface = false;
  lines.markers = false;
  const Image none = render("cloth-springs-none.png", lines);
  const std::array<std::pair<SpringType, Hue>, 3> types = {
      {{SpringType::Structural, Hue::Structural},
       {SpringType::Shear, Hue::Shear},
       {SpringType::Bending, Hue::Bending}}};
  for (const auto& [type, hue] : types) {
    EXPECT_LT(count_hue(none, hue), 200) << name(hue) << " without any spring drawn";
    DrawOptions one = lines;
    one.springs[static_cast<std::size_t>(type)] = true;
    const Image img =
        render(std::string("cloth-springs-") + std::string(to_string(type)) + ".png", one);
    EXPECT_GT(count_hue(img, hue), 2500) << name(hue);
  }
}

TEST_F(HeadlessCloth, TheKinematicSphereHasItsOwnColour) {
  use(cloth_2024());
  camera_.pitch_degrees = -30.0;  // from below: the sphere under the cloth
  const Image below = render("cloth-2024-below.png");
  const SphereBody s = cloth_physics(*world_).sphere(0);
  EXPECT_EQ(
      hue_at(below, camera_, s.center + 0.9 * s.radius * (camera_.eye() - s.center).normalized()),
      Hue::Kinematic);
}

// ---------------------------------------------------------------------------------------------
// `jelly render --replay` on a cloth scene (the grader's frames of cloth-2024): the recorded
// cloth, and the kinematic sphere at the centre recorded after the particles.

TEST(ClothReplay, TheKinematicSphereIsDrawnWhereItWasRecorded) {
  constexpr int w = 640, h = 360;
  const SceneResult scene =
      session::resolve_scene("builtin:cloth-2024", session::default_scenes_dir());
  ASSERT_TRUE(scene) << scene.error->text();
  OrbitCamera camera;
  Vec3Array start;
  double radius = 0.0;
  {
    BackendOptions bo;
    bo.name = "offscreen";
    bo.width = w;
    bo.height = h;
    auto created = create_backend(bo);
    ASSERT_TRUE(created.backend) << created.error;
    Renderer renderer(created.backend->gl(), 0);
    const std::unique_ptr<World> world =
        build_world(*scene.scene, session::tasks_for(*scene.scene));
    ASSERT_EQ(cloth_physics(*world).sphere_count(), 1);
    ASSERT_TRUE(cloth_physics(*world).sphere_is_kinematic(0));
    start = world->state().x;
    radius = cloth_physics(*world).sphere(0).radius;
    camera.frame(renderer.make_drawable(*world)->bounds(), double(w) / h);
  }
  // Frame 0: the sphere where the scene starts it (under the cloth); frame 1: lifted above it.
  const Vec3 under = Vec3::Zero(), above(0.8, 2.8, 0.0);
  fs::create_directories(kArtifacts / "replay");
  const fs::path csv = kArtifacts / "replay" / "cloth-2024.csv";
  {
    std::ofstream out(csv);
    out << "frame,time,particle,x,y,z\n";
    int f = 0;
    for (const Vec3& c : {under, above}) {
      for (Eigen::Index i = 0; i <= start.cols(); ++i) {
        const Vec3 x = i < start.cols() ? Vec3(start.col(i)) : c;
        out << f << "," << 0.5 * f << "," << i << "," << x.x() << "," << x.y() << "," << x.z()
            << "\n";
      }
      ++f;
    }
  }
  const fs::path dir = kArtifacts / "replay" / "cloth-2024";
  fs::remove_all(dir);
  std::vector<std::string> args = {
      "render",      "builtin:cloth-2024", "--replay", csv.string(),      "--frames",  dir.string(),
      "--width",     std::to_string(w),    "--height", std::to_string(h), "--samples", "0",
      "--no-caption"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  ASSERT_EQ(movie::render_command(static_cast<int>(argv.size()), argv.data()), 0);
  const auto load = [&](const char* name) {
    int iw = 0, ih = 0, n = 0;
    unsigned char* data = stbi_load((dir / name).string().c_str(), &iw, &ih, &n, 4);
    Image img;
    if (!data) return img;
    img.width = iw;
    img.height = ih;
    img.rgba.assign(data, data + static_cast<std::size_t>(iw) * ih * 4);
    stbi_image_free(data);
    return img;
  };
  const Image a = load("frame_00000.png"), b = load("frame_00001.png");
  ASSERT_EQ(a.width, w);
  ASSERT_EQ(b.width, w);
  // The sphere's point nearest the eye, lifted: kinematic green in frame 1 only.
  const Vec3 front = above + 0.8 * radius * (camera.eye() - above).normalized();
  EXPECT_EQ(hue_at(b, camera, front), Hue::Kinematic) << pixel_at(b, camera, front);
  EXPECT_NE(hue_at(a, camera, front), Hue::Kinematic) << pixel_at(a, camera, front);
  // A frame with neither the state's particle count nor that plus the kinematic spheres: exit 2.
  const fs::path bad = kArtifacts / "replay" / "cloth-2024-bad.csv";
  {
    std::ofstream out(bad);
    out << "frame,time,particle,x,y,z\n";
    for (Eigen::Index i = 0; i < start.cols() + 2; ++i) out << "0,0," << i << ",0,0,0\n";
  }
  args[3] = bad.string();
  args[5] = (kArtifacts / "replay" / "unused").string();
  argv.clear();
  for (auto& x : args) argv.push_back(x.data());
  EXPECT_EQ(movie::render_command(static_cast<int>(argv.size()), argv.data()), 2);
}

// ---------------------------------------------------------------------------------------------
// Comparison mode: each view's label above it, the shared caption below every view; no text
// over a view (so over no body).

class ComparisonCaption : public ::testing::TestWithParam<std::tuple<std::string, int>> {};

TEST_P(ComparisonCaption, CoversNoView) {
  const auto& [scene_name, count] = GetParam();
  BackendOptions bo;
  bo.name = "offscreen";
  bo.width = kW;
  bo.height = kH;
  auto created = create_backend(bo);
  ASSERT_TRUE(created.backend) << created.error;
  auto renderer = std::make_unique<Renderer>(created.backend->gl());
  SceneResult scene = session::resolve_scene(scene_name, session::default_scenes_dir());
  ASSERT_TRUE(scene) << scene.error->text();
  const std::array<IntegratorKind, 4> kinds = {IntegratorKind::SymplecticEuler, IntegratorKind::RK4,
                                               IntegratorKind::Midpoint,
                                               IntegratorKind::ExplicitEuler};
  std::vector<std::unique_ptr<SimulationRun>> runs;
  std::vector<SimulationRun*> ptrs;
  for (int i = 0; i < count; ++i) {
    RunSetup setup{*scene.scene, kinds[static_cast<std::size_t>(i)], scene.scene->dt, {}};
    if (i == 1) setup.overrides = "springs.structural.ks=1e4";  // a second label line
    runs.push_back(std::make_unique<SimulationRun>(setup, session::tasks_for(setup.scene)));
    ASSERT_TRUE(runs.back()->ok()) << runs.back()->error();
    runs.back()->advance_to(0.05);
    ptrs.push_back(runs.back().get());
  }
  FrameOptions fo;  // caption and labels on
  const auto vps = frame_viewports(count, kW, kH, fo);
  ensure_drawables(*renderer, ptrs);
  OrbitCamera cam;
  cam.frame(drawable_of(*ptrs.front())->bounds(), vps.front().aspect());

  draw_frame(*renderer, ptrs, cam, fo, kW, kH);
  const Image framed = created.backend->read_pixels();
  const std::string stem = "compare-" + scene_name + "-" + std::to_string(count);
  EXPECT_EQ(write_png(kArtifacts / (stem + ".png"), framed), "");
  // The same views with no text at all.
  renderer->begin_frame(kW, kH);
  for (int i = 0; i < count; ++i)
    renderer->draw(*drawable_of(*ptrs[i]), ptrs[i]->simulator()->world(), cam, fo.draw,
                   vps[static_cast<std::size_t>(i)]);
  renderer->end_frame();
  const Image bare = created.backend->read_pixels();
  EXPECT_EQ(write_png(kArtifacts / (stem + "-bare.png"), bare), "");

  const FrameBands bands = frame_bands(count, kH, fo);
  EXPECT_GT(bands.caption, 0);
  EXPECT_GT(bands.label, 0);
  for (int i = 0; i < count; ++i) {
    const Viewport& vp = vps[static_cast<std::size_t>(i)];
    // The body is inside its view: every particle of the cloth or the cube projects into it.
    const Vec3Array& x = ptrs[i]->simulator()->state().x;
    for (Eigen::Index p = 0; p < x.cols(); ++p) {
      const auto q = cam.project(x.col(p), vp.width, vp.height);
      ASSERT_TRUE(q) << "particle " << p << " behind the camera";
      EXPECT_TRUE(q->x() >= 0 && q->y() >= 0 && q->x() < vp.width && q->y() < vp.height)
          << "view " << i << ": particle " << p << " outside its view";
    }
    // No text inside the view: its pixels are those of the bare views (aside from the views'
    // first and last columns, where the 2-px dividers between views lie).
    int differing = 0;
    for (int y = vp.y; y < vp.y + vp.height; ++y)
      for (int px = vp.x + 1; px < vp.x + vp.width - 1; ++px)
        differing += framed.at(px, y) != bare.at(px, y);
    EXPECT_EQ(differing, 0) << "view " << i << ": text over the scene";
    // The label strip above the view holds light text.
    int light = 0;
    for (int y = vp.y - bands.label; y < vp.y; ++y)
      for (int px = vp.x; px < vp.x + vp.width; ++px) {
        const auto c = framed.at(px, y);
        light += c[0] > 180 && c[1] > 180;
      }
    EXPECT_GT(light, 200) << "view " << i << ": no label";
  }
  // The caption strip below every view holds the scene's parameters.
  int light = 0;
  for (int y = kH - bands.caption; y < kH; ++y)
    for (int px = 0; px < kW; ++px) {
      const auto c = framed.at(px, y);
      light += c[0] > 180 && c[1] > 180 && c[2] > 180;
    }
  EXPECT_GT(light, 1000);
  for (const Viewport& vp : vps) EXPECT_LE(vp.y + vp.height, kH - bands.caption);
}

INSTANTIATE_TEST_SUITE_P(A1AndCloth, ComparisonCaption,
                         ::testing::Values(std::make_tuple(std::string("course-2023"), 2),
                                           std::make_tuple(std::string("course-2023"), 4),
                                           std::make_tuple(std::string("cloth-2022"), 2),
                                           std::make_tuple(std::string("cloth-2022"), 4)),
                         [](const auto& param_info) {
                           std::string n = std::get<0>(param_info.param) + "_" +
                                           std::to_string(std::get<1>(param_info.param));
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

}  // namespace
}  // namespace jelly::render
