// PLACEHOLDER until the parameter table lands (helper task). Replaced wholesale.
#include "jelly/params.hpp"

namespace jelly {
std::vector<ParamInfo> scene_parameters(const SceneSpec&) { return {}; }
std::optional<ParamInfo> find_parameter(const SceneSpec&, std::string_view) { return std::nullopt; }
std::optional<std::string> get_parameter(const SceneSpec&, std::string_view) { return std::nullopt; }
std::optional<double> get_number(const SceneSpec&, std::string_view) { return std::nullopt; }
}  // namespace jelly
