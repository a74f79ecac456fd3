#include "jelly/session/overrides.hpp"

namespace jelly::session {

std::optional<std::string> apply_overrides(SceneSpec& scene, std::string_view text) {
  SceneSpec edited = scene;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find_first_of(";\n", start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view item = text.substr(start, end - start);
    if (item.find_first_not_of(" \t\r") != std::string_view::npos)
      if (const auto error = set_assignment(edited, item)) return error->text();
    start = end + 1;
  }
  scene = std::move(edited);
  return std::nullopt;
}

}  // namespace jelly::session
