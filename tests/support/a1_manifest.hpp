// A1's manifest, read from the source tree (tests of A1's probes, hints and rubric).
#pragma once

#include "jelly/manifest.hpp"

namespace jelly::testing {

inline const AssignmentManifest& a1_manifest() {
  static const AssignmentManifest m = read_manifest(std::filesystem::path(JELLY_SOURCE_DIR) /
                                                    "assignments" / "a1" / "assignment.toml");
  return m;
}

}  // namespace jelly::testing
