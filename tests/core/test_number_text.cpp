// jelly::read_double and read_integer (jelly/number_text.hpp): what `--set`, `jelly params` and the
// skeleton's files read. A whole token in C's decimal form, whatever the locale.
#include <gtest/gtest.h>

#include <clocale>
#include <cmath>
#include <limits>

#include "jelly/number_text.hpp"

namespace jelly {
namespace {

TEST(NumberText, ReadsAWholeDecimalTokenWithOneOptionalPlus) {
  EXPECT_EQ(read_double("0.1"), 0.1);
  EXPECT_EQ(read_double("+2.5e-3"), 2.5e-3);
  EXPECT_EQ(read_double("-7"), -7.0);
  EXPECT_EQ(read_double("1e999"), std::nullopt) << "out of range";
  for (const char* bad : {"", "+", "++1", "1.5x", " 1", "1 ", "1,5", "0x1p3", "--1"})
    EXPECT_EQ(read_double(bad), std::nullopt) << "'" << bad << "'";
}

TEST(NumberText, TheClosestDoubleWhateverTheLocale) {
  // A locale whose decimal point is a comma, where one is installed (most machines have C.UTF-8
  // only: then the check is the C locale's, which is what a student's machine may not have).
  const char* before = std::setlocale(LC_ALL, nullptr);
  const std::string saved = before ? before : "C";
  for (const char* name : {"de_DE.UTF-8", "fr_FR.UTF-8", "C.UTF-8"})
    if (std::setlocale(LC_ALL, name)) break;
  EXPECT_EQ(read_double("3.0000000000000004"), 3.0000000000000004);
  EXPECT_EQ(read_double("0.30000000000000004"), 0.1 + 0.2);
  EXPECT_EQ(read_double("1,5"), std::nullopt);
  std::setlocale(LC_ALL, saved.c_str());
}

TEST(NumberText, IntegersAreWholeAndFit) {
  EXPECT_EQ(read_integer("42"), 42);
  EXPECT_EQ(read_integer("+42"), 42);
  EXPECT_EQ(read_integer("-9223372036854775808"), std::numeric_limits<long long>::min());
  for (const char* bad : {"", "+", "4.2", "9223372036854775808", "++1", "1e3", "0x10"})
    EXPECT_EQ(read_integer(bad), std::nullopt) << "'" << bad << "'";
}

}  // namespace
}  // namespace jelly
