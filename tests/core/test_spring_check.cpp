// check_built_springs (jelly/spring_check.hpp): what every body kind does with the springs a
// student's builder returned before the force pass indexes particles with them. A bad spring is
// refused with the builder's name, the spring's number, its particles and rest length, and what
// was expected; good springs pass untouched.
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>

#include "jelly/spring_check.hpp"

namespace jelly {
namespace {

SpringGroup group_of(std::vector<Spring> springs) {
  SpringGroup g;
  g.springs = std::move(springs);
  return g;
}

/// The message check_built_springs throws for `g` in [lo, hi), or "" when it accepts it.
std::string refusal(const SpringGroup& g, int lo, int hi) {
  try {
    check_built_springs(g, lo, hi, "add_structural_springs");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(SpringCheck, SpringsJoiningTwoParticlesOfTheBodyPass) {
  EXPECT_EQ(refusal(group_of({{4, 5, 0.5}, {5, 4, 0.0}, {7, 4, 1e6}}), 4, 8), "");
  EXPECT_EQ(refusal(group_of({}), 0, 0), "") << "a builder may return no spring";
}

TEST(SpringCheck, AnIndexOutsideTheBodyNamesTheSpringAndTheRange) {
  // Particles 4..7 are this body's: 3 is the previous body's, 8 the next one's.
  const std::string low = refusal(group_of({{4, 5, 0.5}, {3, 4, 0.5}}), 4, 8);
  EXPECT_EQ(low,
            "add_structural_springs produced spring #1 joining particles 3 and 4 with rest length "
            "0.500000; expected two different particles in 4..7 and a finite rest length ≥ 0");
  EXPECT_NE(refusal(group_of({{4, 8, 0.5}}), 4, 8).find("spring #0 joining particles 4 and 8"),
            std::string::npos);
  EXPECT_NE(refusal(group_of({{-1, 5, 0.5}}), 4, 8), "");
}

TEST(SpringCheck, ASpringFromAParticleToItselfIsRefused) {
  EXPECT_NE(refusal(group_of({{5, 5, 0.0}}), 4, 8).find("expected two different particles"),
            std::string::npos);
}

TEST(SpringCheck, ANegativeOrNonFiniteRestLengthIsRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_NE(refusal(group_of({{4, 5, -0.1}}), 4, 8).find("rest length -0.100000"),
            std::string::npos);
  EXPECT_NE(refusal(group_of({{4, 5, nan}}), 4, 8), "");
  EXPECT_NE(refusal(group_of({{4, 5, inf}}), 4, 8), "");
}

}  // namespace
}  // namespace jelly
