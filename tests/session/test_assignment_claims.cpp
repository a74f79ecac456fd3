// Which assignment runs a scene (session::claimant, assignment_for): a manifest's `bodies` entry
// "kind" claims every scene of the kind, "kind:variant" only the scenes whose variant (the kind's
// scene_variant) is variant; no claimant and two claimants are errors that name the kind, the
// variant and the assignments (docs/new-assignment.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "jelly/body_kind.hpp"
#include "jelly/linked_assignments.hpp"
#include "jelly/manifest.hpp"
#include "jelly/scene.hpp"
#include "jelly/session/assignments.hpp"

namespace jelly::session {
namespace {

namespace fs = std::filesystem;

const fs::path kScenes = fs::path(JELLY_SOURCE_DIR) / "scenes";

/// A manifest read from its text with `bodies` as given (a TOML array's inside).
AssignmentManifest manifest(const std::string& id, const std::string& bodies) {
  return parse_manifest("id = \"" + id + "\"\nnamespace = \"" + id +
                            "\"\ntitle = \"t\"\nfiles = [\"a.cpp\"]\nbodies = [" + bodies +
                            "]\n[grading]\nautograded_total = 1\n[[task]]\nid = \"T1\"\n"
                            "title = \"t\"\nfile = \"a.cpp\"\npoints = 1\n",
                        "assignments/" + id + "/assignment.toml");
}

/// claimant's error for a scene of `kind` and `variant` ("" when it finds one).
std::string claim_error(const std::vector<const AssignmentManifest*>& all, const std::string& kind,
                        const std::string& variant) {
  try {
    claimant(all, kind, variant);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(AssignmentClaims, ABareKindClaimsEveryVariantOfIt) {
  const AssignmentManifest a = manifest("pa", "\"rope\", \"point\"");
  const AssignmentManifest b = manifest("pb", "\"disc\"");
  const std::vector<const AssignmentManifest*> all{&a, &b};
  EXPECT_EQ(claimant(all, "rope", ""), 0u);
  EXPECT_EQ(claimant(all, "rope", "braided"), 0u);
  EXPECT_EQ(claimant(all, "point", "anything"), 0u);
  EXPECT_EQ(claimant(all, "disc", ""), 1u);
}

TEST(AssignmentClaims, AVariantClaimsOnlyItsVariant) {
  const AssignmentManifest a = manifest("pa", "\"rope:plain\", \"rope:braided\"");
  const AssignmentManifest b = manifest("pb", "\"rope:knotted\"");
  const std::vector<const AssignmentManifest*> all{&a, &b};
  EXPECT_EQ(claimant(all, "rope", "plain"), 0u);
  EXPECT_EQ(claimant(all, "rope", "braided"), 0u);
  EXPECT_EQ(claimant(all, "rope", "knotted"), 1u);
  EXPECT_FALSE(a.claims("rope", "knotted"));
  EXPECT_FALSE(a.claims("rope", "")) << "a variant claim does not take a scene without variant";
  EXPECT_FALSE(a.claims("disc", "plain"));
}

TEST(AssignmentClaims, TwoClaimantsAreAnErrorNamingBoth) {
  const AssignmentManifest a = manifest("pa", "\"rope\"");
  const AssignmentManifest b = manifest("pb", "\"rope:knotted\"");
  const AssignmentManifest c = manifest("pc", "\"rope:plain\"");
  EXPECT_EQ(claim_error({&a, &b, &c}, "rope", "knotted"),
            "the scene's rope body of variant \"knotted\" is simulated by several assignments "
            "(pa, pb); build one of them only (docs/new-assignment.md)");
  EXPECT_EQ(claim_error({&a, &c}, "rope", ""), "")
      << "pc's variant claim does not take a rope without variant";
  const AssignmentManifest d = manifest("pd", "\"rope\"");
  EXPECT_EQ(claim_error({&a, &d}, "rope", ""),
            "the scene's rope body is simulated by several assignments (pa, pd); build one of "
            "them only (docs/new-assignment.md)");
}

TEST(AssignmentClaims, NoClaimantNamesTheKindAndTheVariant) {
  const AssignmentManifest a = manifest("pa", "\"rope:plain\"");
  const AssignmentManifest b = manifest("pb", "\"disc\"");
  EXPECT_EQ(claim_error({&a, &b}, "rope", "knotted"),
            "no assignment in this program simulates a rope body of variant \"knotted\" (a "
            "manifest's bodies = [\"rope:knotted\"] or [\"rope\"]) (it has: pa, pb)");
  EXPECT_EQ(claim_error({&a, &b}, "cone", ""),
            "no assignment in this program simulates a cone body (it has: pa, pb)");
  EXPECT_EQ(claim_error({}, "cone", ""),
            "no assignment in this program simulates a cone body (it has: none)");
}

// The skeleton kind's variant is its scene's body.mode; every other kind of this tree has none.
TEST(AssignmentClaims, TheSkeletonsVariantIsItsMode) {
  const BodyKindModule* skeleton = find_body_kind("skeleton");
  if (!skeleton) GTEST_SKIP() << "this build links no skeleton kind";
  const struct {
    const char* scene;
    const char* variant;
  } cases[] = {{"hw2-fk-2022.toml", "playback"},
               {"hw2-warp-2022.toml", "warp"},
               {"hw2-blend-2022.toml", "blend"}};
  for (const auto& c : cases) {
    if (!fs::exists(kScenes / c.scene)) continue;  // a release without the skeleton's scenes
    const SceneResult r = load_scene(kScenes / c.scene);
    ASSERT_TRUE(r) << c.scene << ": " << r.error->text();
    EXPECT_EQ(skeleton->scene_variant(*r.scene), c.variant) << c.scene;
  }
  EXPECT_EQ(skeleton->scene_variant(SceneSpec{}), "playback") << "body.mode's default";
  for (const BodyKindModule* kind : body_kinds()) {
    if (kind == skeleton) continue;
    EXPECT_EQ(kind->scene_variant(SceneSpec{}), "") << kind->name();
  }
}

// The tree's linked assignments: every scene of scenes/ has exactly one, and a skeleton scene's
// is the one whose manifest claims its mode.
TEST(AssignmentClaims, EveryShippedSceneHasOneLinkedAssignment) {
  int checked = 0;
  for (const auto& e : fs::recursive_directory_iterator(kScenes)) {
    if (e.path().extension() != ".toml") continue;
    const SceneResult r = load_scene(e.path());
    ASSERT_TRUE(r) << e.path() << ": " << r.error->text();
    const BodyKindModule& kind = body_kind_of(*r.scene);
    bool claimed = false;
    for (const LinkedAssignment& a : linked_assignments())
      claimed = claimed || manifest_of(a).claims(kind.name(), kind.scene_variant(*r.scene));
    if (!claimed) continue;  // a scene of an assignment this build does not link
    const LinkedAssignment& a = assignment_for(*r.scene);
    EXPECT_TRUE(manifest_of(a).claims(kind.name(), kind.scene_variant(*r.scene))) << e.path();
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

}  // namespace
}  // namespace jelly::session
