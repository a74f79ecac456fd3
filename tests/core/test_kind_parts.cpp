// KindParts (jelly/kind_parts.hpp), where a scene keeps what only its body's module knows
// (SceneSpec::body_data): one value per type, made with its defaults on first use, read without
// making one, copied with the scene, and never moved once made.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "jelly/kind_parts.hpp"
#include "jelly/scene_spec.hpp"

namespace jelly {
namespace {

struct RopeSpec {
  int beads = 12;
  double length = 2.0;
};
struct Knots {
  std::vector<int> at;
};

TEST(KindParts, ReadingMakesNothingAndGivesTheTypesDefaults) {
  const KindParts parts;
  EXPECT_EQ(parts.find<RopeSpec>(), nullptr);
  EXPECT_EQ(parts.get_or_default<RopeSpec>().beads, 12);
  EXPECT_EQ(parts.find<RopeSpec>(), nullptr) << "get_or_default made a part";
}

TEST(KindParts, OnePartPerTypeAndEachKeepsItsPlace) {
  KindParts parts;
  RopeSpec& rope = parts.get<RopeSpec>();
  rope.beads = 40;
  for (int i = 0; i < 100; ++i) parts.get<Knots>().at.push_back(i);  // another type, made once
  parts.get<std::string>() = "a third";
  EXPECT_EQ(&parts.get<RopeSpec>(), &rope) << "a part moved when others were made";
  EXPECT_EQ(parts.get<RopeSpec>().beads, 40);
  EXPECT_EQ(parts.find<Knots>()->at.size(), 100u);
  EXPECT_EQ(*parts.find<std::string>(), "a third");
}

TEST(KindParts, ASceneCopiesItsBodysDataAndTheCopiesAreIndependent) {
  SceneSpec a;
  a.body_data.get<RopeSpec>().length = 5.5;
  SceneSpec b = a;
  b.body_data.get<RopeSpec>().length = 1.0;
  EXPECT_EQ(a.body_data.get_or_default<RopeSpec>().length, 5.5);
  EXPECT_EQ(b.body_data.get_or_default<RopeSpec>().length, 1.0);
  SceneSpec c;
  c = a;
  EXPECT_EQ(c.body_data.get_or_default<RopeSpec>().length, 5.5);
}

}  // namespace
}  // namespace jelly
