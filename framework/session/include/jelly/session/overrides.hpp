// A run's own parameters as one line of text: "key=value; …" (comparison mode, --slot-set).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "jelly/scene.hpp"

namespace jelly::session {

/// Applies "key=value" assignments separated by ';' or new lines (the keys of `jelly params`, as
/// `--set` takes them; values may contain commas, e.g. body.center=-5,11,0) to `scene`. Returns
/// the first error ("springs.shear.ks: …") and leaves the scene unchanged then; blank is fine.
std::optional<std::string> apply_overrides(SceneSpec& scene, std::string_view text);

}  // namespace jelly::session
