// The non-ASCII guard in front of toml++ 3.3.0 (framework/manifest, jelly/toml_text.hpp): valid
// TOML with non-ASCII text in every place a string or comment may stand passes it (and toml++
// reads it); text where toml++ would read such a character outside a string is refused, with the
// place.
#include <string>

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "jelly/toml_text.hpp"

namespace jelly {
namespace {

TEST(TomlText, NonAsciiInEveryPlaceAStringOrCommentMayStandPasses) {
  for (const std::string text : {
           "# é\nname = \"é\" # ü\n",
           "name=\"é\"\n",
           "\"é\" = 1\n",
           "a.\"é\".b = 'é'\n",
           "[\"é\"]\nx = 1\n",
           "[a.'é']\n[[\"ö\".list]]\nx = 1\n",
           "x = [\"é\", 'ü', \"\"\"ö\"\"\"]\n",
           "x = [\n  1, # é\n  \"é\",\n]\n",
           "x = {a = \"é\", \"ü\" = 'ö'}\n",
           "x = \"\"\"\né\n\"\"\"\ny = '''\né'''\n",
           "x = \"\"\"\"é\"\"\"\"\n",
           "x = \"\\\"é\\\\\"\n",
           "t = 1979-05-27 07:32:00 # é\n",
           "n = -1.5e3 # é\n",
       }) {
    EXPECT_FALSE(toml_non_ascii_outside_strings(text)) << text;
    EXPECT_NO_THROW(toml::parse(text)) << text;
  }
}

TEST(TomlText, NonAsciiWhereToml33WouldMisreadItIsRefusedWithThePlace) {
  const struct {
    std::string text;
    int line, column;
  } cases[] = {
      {"x = 1é\n", 1, 6},
      {"é = 1\n", 1, 1},
      {"x = 1\n  \u00a0\n", 2, 3},
      {"x = \"a\"é\n", 1, 8},
      {"x = \"\"\"a\"\"\"é\n", 1, 12},
      {"x = [[[+[[[\"rk4\"[[\"~~Ý\n", 1, 22},  // the scene fuzzer's: toml++ scans "+..." on
      {"x = 1\"é\"\n", 1, 7},
      {"x = inf='é'\n", 1, 10},
      {"x = .'é'\n", 1, 7},
      {"x = {a = 1\"é\"}\n", 1, 12},
      {"x = [1, 2\n  3\"é\"]\n", 2, 5},
      {"x = \"\"\"a \\\n\n  é\"\"\"\n", 3, 3},  // after a line-ending backslash
  };
  for (const auto& c : cases) {
    const auto at = toml_non_ascii_outside_strings(c.text);
    ASSERT_TRUE(at) << c.text;
    EXPECT_EQ(at->line, c.line) << c.text;
    EXPECT_EQ(at->column, c.column) << c.text;
  }
}

}  // namespace
}  // namespace jelly
