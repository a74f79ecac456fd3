// The terminal tables every program prints (jelly/cli_common/text_table.hpp): display widths of
// UTF-8 text, and columns sized to their content and padded by display width (issue 28).
#include <gtest/gtest.h>

#include <string>

#include "jelly/cli_common/text_table.hpp"

namespace {

using jelly::cli::display_width;
using jelly::cli::TextTable;

TEST(TextTable, DisplayWidthCountsColumnsNotBytes) {
  EXPECT_EQ(display_width("Sphere-sphere"), 13u);
  EXPECT_EQ(display_width("Cloth\xE2\x80\x93sphere"), 12u);  // en dash: 3 bytes, 1 column
  EXPECT_EQ(display_width("e\xCC\x81"), 1u);                 // e + combining acute
  EXPECT_EQ(display_width("\xE6\xBC\xA2\xE5\xAD\x97"), 4u);  // two CJK ideographs: wide
  EXPECT_EQ(display_width("\xF0\x9F\x98\x80"), 2u);          // an emoji
  EXPECT_EQ(display_width("a\xFF"
                          "b"),
            3u);                             // a stray byte: one column
  EXPECT_EQ(display_width("\xE2\x80"), 2u);  // a cut character: its bytes
}

TEST(TextTable, ColumnsAreAsWideAsTheirWidestCellByDisplayWidth) {
  TextTable t(" ");
  t.align_right(2);
  t.add_row({"A2.T6", "Cloth\xE2\x80\x93sphere collision", "10.00", "PASS"});
  t.add_row({"A2.T7", "Sphere\xE2\x80\x93sphere collision", "5.00", "FAIL"});
  t.add_row({"A2.T9", "Implicit Euler (predictor-corrector)", "10.00", "PASS"});
  EXPECT_EQ(t.str(),
            "A2.T6 Cloth\xE2\x80\x93sphere collision               10.00 PASS\n"
            "A2.T7 Sphere\xE2\x80\x93sphere collision               5.00 FAIL\n"
            "A2.T9 Implicit Euler (predictor-corrector) 10.00 PASS\n");
  EXPECT_EQ(t.row(1), "A2.T7 Sphere\xE2\x80\x93sphere collision               5.00 FAIL");
  EXPECT_EQ(t.str("  ").substr(0, 8), "  A2.T6 ");
}

TEST(TextTable, TheLastCellIsNotPaddedAndRowsMayBeShort) {
  TextTable t;
  t.add_row({"key", "value", "description"});
  t.add_row({"a.long.key", "1"});
  EXPECT_EQ(t.str(), "key         value  description\na.long.key  1\n");
}

}  // namespace
