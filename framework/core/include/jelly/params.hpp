// The declaration of every scene parameter, in one place (house style §14).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "jelly/scene_spec.hpp"

namespace jelly {

enum class ParamType { Real, Integer, Bool, Vector3, Choice, Text };

/// One declared parameter: the loader validates against it, `--set` parses with it, the viewer
/// draws a widget from it, and `jelly params` prints it.
struct ParamInfo {
  std::string key;  ///< dotted name as in the file: "springs.shear.ks", "terrain.floor.epsilon"
  ParamType type = ParamType::Real;
  std::string unit;          ///< "N/m", "m", "s", "" for dimensionless
  std::string default_text;  ///< the default, as text
  double min = 0.0;  ///< lower bound (Real, Integer; per component for Vector3 when bounded)
  double max = 0.0;  ///< upper bound
  bool min_inclusive = true;
  bool max_inclusive = true;
  bool bounded = false;              ///< whether min/max apply
  std::vector<std::string> choices;  ///< allowed values for Choice
  std::string description;           ///< one line for help texts and tooltips
};

/// Every parameter that applies to `scene`: the global ones (the body keys of its body kind, the
/// gravity keys when it has gravity), then each collection's keys for each of its elements
/// (springs.<type>.* for every spring type, ks and kd only for the types it has;
/// terrain.<name>.* for each of its terrains). Order is stable (the order of the declaration
/// table).
std::vector<ParamInfo> scene_parameters(const SceneSpec& scene);

/// The declaration of one key in `scene`, or nullopt when the key is not declared.
std::optional<ParamInfo> find_parameter(const SceneSpec& scene, std::string_view key);

/// The current value of a parameter as text in the form set_parameter accepts.
std::optional<std::string> get_parameter(const SceneSpec& scene, std::string_view key);

/// Sets a declared parameter from text ("5000", "-5,11,0", "true", "rk4"), validated like the
/// file; key as in the file ("springs.shear.ks", "body.center", "terrain.floor.restitution",
/// "simulation.dt"). Returns the error (file "--set") or nullopt.
std::optional<SceneError> set_parameter(SceneSpec& scene, std::string_view key,
                                        std::string_view value);

/// The same from one "key=value" (as `--set` takes it; spaces around key and value are ignored,
/// the value may contain commas). Without '=' or with an empty key: an error saying so.
std::optional<SceneError> set_assignment(SceneSpec& scene, std::string_view assignment);

/// The value of a Real or Integer parameter as a double (for sliders); nullopt otherwise.
std::optional<double> get_number(const SceneSpec& scene, std::string_view key);

/// The reference table of every declared parameter as Markdown (key, where it applies, type,
/// unit, default, valid range, description), in declaration order: docs/scenes.md embeds it and a
/// test keeps the two equal; `jelly params` can print it.
std::string parameter_reference_markdown();

}  // namespace jelly
