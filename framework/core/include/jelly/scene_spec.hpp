// What a scene file describes (SceneSpec), and a scene input error. The parameters that read and
// write it are declared in params.hpp; loading and building a World are in scene.hpp.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "jelly/integrator.hpp"
#include "jelly/kind_parts.hpp"
#include "jelly/spring.hpp"
#include "jelly/terrain.hpp"

namespace jelly {

/// The acceleration a scene's gravity has unless it says otherwise (gravity.enabled = true) [m/s²].
inline Vec3 default_gravity() { return Vec3(0.0, -9.8, 0.0); }

/// Coefficients of one spring type; `enabled` is false when the scene does not name the type.
struct SpringSettings {
  bool enabled = false;
  double ks = 2000.0;  ///< [N/m]
  double kd = 60.0;    ///< [N·s/m]
};

/// A scene's kind of body: its `body.type` name, the name a body module registers
/// (jelly/body_kind.hpp, framework/bodies/<kind>/). Compared by name, so a kind the framework has
/// never heard of is one more module, not an edit here. Each kind's header names its own.
struct BodyKind {
  std::string_view name;
};
/// The kind a scene has when it names none: the first kind this program registers (the default of
/// `body.type`, jelly/body_kind.hpp).
BodyKind default_body_kind();
inline bool operator==(const BodyKind& a, const BodyKind& b) { return a.name == b.name; }
inline bool operator!=(const BodyKind& a, const BodyKind& b) { return !(a == b); }

/// Everything a scene file says, validated.
struct SceneSpec {
  std::string name;         ///< [scene] name
  std::string description;  ///< [scene] description
  std::string source;       ///< the file it came from ("" when built in code)

  IntegratorKind integrator = IntegratorKind::ExplicitEuler;  ///< simulation.integrator
  double dt = 0.001;                                          ///< simulation.dt [s]
  double duration = 10.0;                                     ///< simulation.duration [s]
  bool auto_dt = false;  ///< simulation.auto_dt: derive a stable step ≤ dt (jelly/auto_step.hpp)

  std::optional<Vec3> gravity;  ///< gravity.acceleration; nullopt: no gravity term at all

  BodyKind body_kind = default_body_kind();
  /// What the scene says of its body that only the body's module knows (its size, its obstacles):
  /// each kind reads and writes its own structs here through its header's accessors
  /// (framework/bodies/<kind>/include/).
  KindParts body_data;

  SpringSettings structural;  ///< springs.structural
  SpringSettings shear;       ///< springs.shear (face and body diagonals)
  SpringSettings shear_body;  ///< springs.shear_body: when enabled, body diagonals use these
  SpringSettings bending;     ///< springs.bending

  std::vector<Terrain> terrains;  ///< in scene order (none when the body's kind refuses them)
};

/// A scene input error: the file, the key (dotted path) and line where known, and what was
/// expected.
struct SceneError {
  std::string file;     ///< path as given, or "<string>"/"--set"
  std::string key;      ///< e.g. "body.n", "terrain.floor.normal"; empty for syntax errors
  int line = 0;         ///< 1-based; 0 when unknown
  int column = 0;       ///< 1-based; 0 when unknown
  std::string message;  ///< what is wrong and what was expected

  /// "scenes/x.toml:12:3: body.n: must be an integer ≥ 2, got 1"
  std::string text() const;
};

}  // namespace jelly
