// What `jelly study effects` measures on a cube (docs/parameters.md, "What is measured"): the
// cave-in, from the volume inside the cube's outer surface. Used by the cube's kind module only.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "jelly/body_kind.hpp"

namespace jelly::bodies {

/// The cube kind's study of one run (BodyKindModule::study): the cave-in of the world's first
/// cube when `measures` names cave_in; nullptr otherwise (or when the world has no cube).
std::unique_ptr<BodyStudy> make_cube_study(const World& world, const State& start,
                                           const std::vector<std::string>& measures);

/// The cube's measures (BodyKindModule::measures): the cave-in.
const std::vector<BodyMeasure>& cube_measures();

}  // namespace jelly::bodies
