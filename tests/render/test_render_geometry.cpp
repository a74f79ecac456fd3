// Draw proxies and camera on the null backend (no GL): the geometry the renderer draws is the
// physics' geometry. (The clock and the runs' history: tests/session.)
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "jelly/a1/task_table.hpp"
#include "jelly/bodies/cube/view/cube_view.hpp"
#include "jelly/render/backend.hpp"
#include "jelly/render/frame.hpp"
#include "jelly/render/meshes.hpp"
#include "jelly/session/scene_catalog.hpp"
#include "jelly/session/simulation_run.hpp"

namespace jelly::render {
namespace {

using session::RunSetup;
using session::SimulationRun;

SceneSpec course_scene() {
  SceneResult r = session::resolve_scene("course-2023", session::default_scenes_dir());
  EXPECT_TRUE(r) << (r.error ? r.error->text() : "");
  return r ? *r.scene : course_2023_scene();
}

TEST(RenderMeshes, PlaneHoleInnerRingIsThePhysicalRadius) {
  const Plane p = std::get<Plane>(terrain_preset("course-2023-floor")->shape);
  const Mesh m = plane_mesh(p, Vec3::Zero(), 25.0);
  double inner_min = 1e9, inner_max = 0.0;
  for (const auto& v : m.positions) {
    const Vec3 d = v.cast<double>() - p.hole_center;
    const double r = std::hypot(d.x(), d.z());
    EXPECT_GE(r, p.hole_radius * (1 - 1e-6)) << "a vertex inside the hole";
    EXPECT_NEAR(v.y(), 0.0, 1e-6);
    if (r < p.hole_radius + 1e-3) {
      inner_min = std::min(inner_min, r);
      inner_max = std::max(inner_max, r);
    }
  }
  // The inner ring lies on the hole's circle (float precision).
  EXPECT_NEAR(inner_min, p.hole_radius, 1e-5);
  EXPECT_NEAR(inner_max, p.hole_radius, 1e-5);
}

TEST(RenderMeshes, BowlCapEndsAtTheRimAndLiesOnTheSphere) {
  const Bowl b = std::get<Bowl>(terrain_preset("course-2023-bowl")->shape);
  const Mesh m = bowl_mesh(b);
  double top = -1e9;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const Vec3 x = m.positions[i].cast<double>();
    EXPECT_NEAR((x - b.center).norm(), b.radius, 1e-4);
    EXPECT_LE(x.y(), b.rim_height + 1e-5);
    top = std::max(top, x.y());
    // Normals point inwards, towards the centre.
    EXPECT_GT(m.normals[i].cast<double>().dot(b.center - x), 0.0);
  }
  EXPECT_NEAR(top, b.rim_height, 1e-5);
  // The 2023 bowl's rim is the hole's circle: the same radius.
  EXPECT_NEAR(b.rim_radius(),
              std::get<Plane>(terrain_preset("course-2023-floor")->shape).hole_radius, 1e-12);
}

TEST(RenderMeshes, JellySurfaceCoversTheOuterFacesWithOutwardNormals) {
  CubeSpec spec;
  spec.n = 4;
  spec.edge = 3.0;
  spec.center = Vec3(1.0, 5.0, -2.0);
  spec.rotation_degrees = 30.0;
  const CubeLattice lattice(spec, 7);
  cube_view::JellySurface surface(lattice);
  const Mesh& m = surface.mesh();
  EXPECT_EQ(m.positions.size(), 6u * 4 * 4);
  EXPECT_EQ(m.indices.size(), 6u * 3 * 3 * 6);
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const Vec3 out = m.positions[i].cast<double>() - spec.center;
    EXPECT_GT(m.normals[i].cast<double>().dot(out), 0.0) << "vertex " << i;
  }
  // Every triangle winds outwards.
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const Vec3 a = m.positions[m.indices[t]].cast<double>(),
               b = m.positions[m.indices[t + 1]].cast<double>(),
               c = m.positions[m.indices[t + 2]].cast<double>();
    EXPECT_GT((b - a).cross(c - a).dot((a + b + c) / 3.0 - spec.center), 0.0);
  }
  // update() follows the particles: translate the state, the mesh follows.
  Vec3Array x(3, 7 + lattice.particle_count());
  x.setZero();
  x.rightCols(lattice.particle_count()) = lattice.initial_positions().colwise() + Vec3(0, -2, 0);
  surface.update(x);
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    EXPECT_NEAR(m.positions[i].y(), x(1, surface.particles()[i]), 1e-5);
}

TEST(RenderCamera, TargetProjectsToTheViewportCentre) {
  OrbitCamera cam;
  cam.target = Vec3(2.0, 3.0, -1.0);
  cam.distance = 20.0;
  const auto p = cam.project(cam.target, 1280, 720);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->x(), 640.0, 1e-3);
  EXPECT_NEAR(p->y(), 360.0, 1e-3);
  // Up in the world is up on the screen (smaller y).
  EXPECT_LT(cam.project(cam.target + Vec3::UnitY(), 1280, 720)->y(), 360.0);
  // A point behind the camera has no projection.
  EXPECT_FALSE(cam.project(cam.eye() + (cam.eye() - cam.target), 1280, 720));
}

TEST(RenderCamera, FramingKeepsTheJellyTheHoleAndTheBowlInView) {
  SimulationRun run(RunSetup::from_scene(course_scene()), a1::task_table());
  ASSERT_TRUE(run.ok()) << run.error();
  Renderer renderer(nullptr);
  auto d = renderer.make_drawable(run.simulator()->world());
  OrbitCamera cam;
  cam.frame(d->bounds(), 16.0 / 9.0);
  std::vector<Vec3> points;
  const Vec3Array& x = run.simulator()->state().x;
  for (Eigen::Index i = 0; i < x.cols(); ++i) points.push_back(x.col(i));
  for (const Terrain& t : run.simulator()->world().terrains()) {
    if (const auto* p = std::get_if<Plane>(&t.shape); p && p->has_hole)
      for (int k = 0; k < 16; ++k) {
        const double a = k * 3.14159265358979 / 8;
        points.push_back(p->hole_center + p->hole_radius * Vec3(std::cos(a), 0.0, std::sin(a)));
      }
    if (const auto* b = std::get_if<Bowl>(&t.shape))
      points.push_back(b->center - b->radius * Vec3::UnitY());
  }
  for (const Vec3& pt : points) {
    const auto p = cam.project(pt, 1280, 720);
    ASSERT_TRUE(p);
    EXPECT_GE(p->x(), 0.0);
    EXPECT_LE(p->x(), 1280.0);
    EXPECT_GE(p->y(), 0.0);
    EXPECT_LE(p->y(), 720.0);
  }
}

TEST(RenderNullBackend, DrawsWithoutGlAndFollowsTheState) {
  auto backend = create_backend({"null", 320, 200, "", false});
  ASSERT_TRUE(backend.backend) << backend.error;
  EXPECT_EQ(backend.backend->gl(), nullptr);
  SimulationRun run(RunSetup::from_scene(course_scene()), a1::task_table());
  ASSERT_TRUE(run.ok());
  Renderer renderer(backend.backend->gl());
  OrbitCamera cam;
  std::vector<SimulationRun*> runs{&run};
  draw_frame(renderer, runs, cam, FrameOptions{}, 320, 200);
  ASSERT_NE(drawable_of(run), nullptr);
  const auto* cube = drawable_of(run)->body<cube_view::CubeDrawable>();
  ASSERT_NE(cube, nullptr);
  ASSERT_EQ(cube->surfaces().size(), 1u);
  EXPECT_EQ(drawable_of(run)->terrain_meshes().size(), run.simulator()->world().terrains().size());
  const int p0 = cube->surfaces()[0].particles()[0];
  run.simulator()->world().state().x.col(p0) += Vec3(0, 1, 0);
  draw_frame(renderer, runs, cam, FrameOptions{}, 320, 200);
  EXPECT_FLOAT_EQ(cube->surfaces()[0].mesh().positions[0].y(),
                  static_cast<float>(run.simulator()->world().state().x(1, p0)));
  EXPECT_EQ(backend.backend->read_pixels().width, 320);
}

TEST(RenderBackends, UnknownNameIsAnErrorThatListsTheChoices) {
  auto r = create_backend({"vulkan", 320, 200, "", false});
  EXPECT_FALSE(r.backend);
  EXPECT_NE(r.error.find("auto, window, offscreen or null"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace jelly::render
