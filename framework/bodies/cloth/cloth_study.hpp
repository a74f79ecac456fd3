// What `jelly study effects` measures on a cloth (docs/parameters.md, "What is measured"): its sag
// and swing, and how deep its particles sink into the spheres. Used by the cloth's kind module
// only.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "jelly/body_kind.hpp"

namespace jelly::bodies {

/// The cloth kind's study of one run (BodyKindModule::study): the sag and the swing of the
/// cloth's centre of mass from `look`, and the sink when `measures` names it and the world has
/// spheres.
std::unique_ptr<BodyStudy> make_cloth_study(const World& world, const State& start,
                                            const StudyLook& look,
                                            const std::vector<std::string>& measures);

/// The cloth's measures (BodyKindModule::measures): the sag, the swing and the sink.
const std::vector<BodyMeasure>& cloth_measures();

/// What the help adds to its note on measures needing a contact.
std::string_view cloth_contact_help();

}  // namespace jelly::bodies
