// Scenes: what a scene file describes, how it is loaded and validated, and how it becomes a World.
//
// Every parameter is declared once (params.hpp: name, unit, default, range, description); the
// loader, `jelly run --set`, the viewer's panels and the grader all go through that declaration.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "jelly/cube.hpp"
#include "jelly/integrator.hpp"
#include "jelly/spring.hpp"
#include "jelly/terrain.hpp"
#include "jelly/world.hpp"

namespace jelly {

/// Coefficients of one spring type; `enabled` is false when the scene does not name the type.
struct SpringSettings {
  bool enabled = false;
  double ks = 2000.0;  ///< [N/m]
  double kd = 60.0;    ///< [N·s/m]
};

/// A body given particle by particle (the two-particle spring, particle clouds).
struct ParticleBodySpec {
  Vec3Array positions;   ///< 3×N [m]
  Vec3Array velocities;  ///< 3×N [m/s] (zero when the scene gives none)
  double mass = 1.0;     ///< every particle [kg]
  std::vector<Spring> springs;  ///< explicit springs (rest length given or from positions)
  SpringType spring_type = SpringType::Structural;  ///< whose coefficients they use
};

enum class BodyKind { Cube, Particles };

/// Everything a scene file says, validated.
struct SceneSpec {
  std::string name;         ///< [scene] name
  std::string description;  ///< [scene] description
  std::string source;       ///< the file it came from ("" when built in code)

  IntegratorKind integrator = IntegratorKind::ExplicitEuler;  ///< simulation.integrator
  double dt = 0.001;        ///< simulation.dt [s]
  double duration = 10.0;   ///< simulation.duration [s]
  bool auto_dt = false;     ///< simulation.auto_dt: derive a stable step ≤ dt (jelly/auto_step.hpp)

  std::optional<Vec3> gravity;  ///< gravity.acceleration; nullopt: no gravity term at all

  BodyKind body_kind = BodyKind::Cube;
  CubeSpec cube;                ///< when body_kind == Cube
  ParticleBodySpec particles;   ///< when body_kind == Particles

  SpringSettings structural;  ///< springs.structural
  SpringSettings shear;       ///< springs.shear (face and body diagonals)
  SpringSettings shear_body;  ///< springs.shear_body: when enabled, body diagonals use these
  SpringSettings bending;     ///< springs.bending

  std::vector<Terrain> terrains;  ///< in scene order
};

/// A scene input error: the file, the key (dotted path) and line where known, and what was expected.
struct SceneError {
  std::string file;     ///< path as given, or "<string>"/"--set"
  std::string key;      ///< e.g. "body.n", "terrain.floor.normal"; empty for syntax errors
  int line = 0;         ///< 1-based; 0 when unknown
  int column = 0;       ///< 1-based; 0 when unknown
  std::string message;  ///< what is wrong and what was expected

  /// "scenes/x.toml:12:3: body.n: must be an integer ≥ 2, got 1"
  std::string text() const;
};

/// Either a scene or the first error found.
struct SceneResult {
  std::optional<SceneSpec> scene;
  std::optional<SceneError> error;
  explicit operator bool() const { return scene.has_value(); }
};

/// Reads, parses and validates a scene file. Never throws, never exits, writes nothing.
SceneResult load_scene(const std::filesystem::path& path);
/// Parses and validates scene text; `source_name` names it in errors (used by tests and the fuzzer).
SceneResult parse_scene(std::string_view text, std::string_view source_name);

/// Sets a declared parameter from text ("5000", "-5,11,0", "true", "rk4"), validated like the
/// file; key as in the file ("springs.shear.ks", "body.center", "terrain.floor.restitution",
/// "simulation.dt"). Returns the error (file "--set") or nullopt.
std::optional<SceneError> set_parameter(SceneSpec& scene, std::string_view key,
                                        std::string_view value);

/// The same from one "key=value" (as `--set` takes it; spaces around key and value are ignored,
/// the value may contain commas). Without '=' or with an empty key: an error saying so.
std::optional<SceneError> set_assignment(SceneSpec& scene, std::string_view assignment);

/// Writes a scene back as TOML that load_scene reads to the same SceneSpec.
std::string to_toml(const SceneSpec& scene);

/// Builds the World a scene describes, with the given task implementations. Only the effects the
/// scene names are built: absent spring types are not built, absent terrains not added, no gravity
/// means no gravity term (contract §7).
std::unique_ptr<World> build_world(const SceneSpec& scene, const TaskTable& tasks);

/// Named terrain presets: "course-2023-floor", "course-2023-bowl", "course-2021-plane",
/// "course-2021-sphere", "course-2021-bowl", "course-2021-tilted". nullopt when unknown.
std::optional<Terrain> terrain_preset(std::string_view name);
/// All preset names.
std::vector<std::string_view> terrain_preset_names();

/// The course's 2023 scene as scenes/course-2023.toml describes it (n = 10 cube at (−4.8, 11, 0),
/// ks 2000 / kd 60 on every spring type, gravity, the floor with its hole then the bowl, h = 0.001,
/// 10 s, symplectic Euler), built in code: for tests and benchmarks that must not depend on scene
/// files, and for the viewer when the file is missing.
SceneSpec course_2023_scene();

}  // namespace jelly
