// Small ASF and AMC texts for the skeleton module's tests, and the checks of a reader's error.
#pragma once

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "jelly/skeleton/skeleton_files.hpp"

namespace jelly::skeleton::test {

// A valid ASF of three bones: root, a (rx ry rz, with limits), b (no channels). The line numbers
// are the tests' (kAsf line n is the n-th line), EOF is line 38.
inline const std::vector<std::string> kAsf = {
    ":version 1.10",  // 1
    ":name test",
    ":units",
    "  mass 1.0",
    "  length 0.45",
    "  angle deg",  // 6
    ":documentation",
    "  free text, ignored",
    ":root",  // 9
    "   order TX TY TZ RX RY RZ",
    "   axis XYZ",
    "   position 0 0 0",
    "   orientation 0 0 0",
    ":bonedata",  // 14
    "  begin",
    "     id 1",
    "     name a",
    "     direction 0 1 0",
    "     length 2",  // 19
    "     axis 0 0 10 XYZ",
    "    dof rx ry rz",
    "    limits (-10 10)",  // 22
    "           (-20 20)",
    "           (-30 30)",
    "  end",  // 25
    "  begin",
    "     id 2",
    "     name b",
    "     direction 1 0 0",
    "     length 1",  // 30
    "     axis 0 0 0 XYZ",
    "  end",
    ":hierarchy",  // 33
    "  begin",
    "    root a",
    "    a b",  // 36
    "  end",
};
inline constexpr int kAsfEndOfFile = 38;

// A valid AMC of kAsf's skeleton: two frames, the second without bone a.
inline const std::vector<std::string> kAmc = {
    "# comment",  // 1
    ":FULLY-SPECIFIED",
    ":DEGREES",
    "1",  // 4
    "root 1 2 3 4 5 6",
    "a 7 8 9",  // 6
    "2",
    "root 1 2 3 4 5 6",  // 8
};
inline constexpr int kAmcEndOfFile = 9;

// The lines joined with '\n' (and a final one), with line `n` (1-based) replaced by `with` when
// n > 0 ("# gone" blanks a line and keeps the numbering).
inline std::string text_of(std::vector<std::string> lines, int n = 0,
                           const std::string& with = "") {
  if (n > 0) lines.at(n - 1) = with;
  std::string out;
  for (const std::string& l : lines) out += l + "\n";
  return out;
}

inline Skeleton small_skeleton() {
  const SkeletonResult r = parse_asf(text_of(kAsf), "t.asf", 0.2);
  EXPECT_TRUE(r) << (r.error ? r.error->text() : "");
  return r ? *r.skeleton : Skeleton{};
}

// The reader failed, returned nothing, and named the file, the line and `expected` in its message.
template <class Result>
void expect_error(const Result& r, const std::string& file, int line, const std::string& expected) {
  ASSERT_FALSE(r) << "expected an error at line " << line << " (" << expected << ")";
  ASSERT_TRUE(r.error.has_value());
  EXPECT_EQ(r.error->file, file);
  EXPECT_EQ(r.error->line, line) << r.error->text();
  EXPECT_NE(r.error->message.find(expected), std::string::npos)
      << r.error->text() << "\n  expected: " << expected;
  EXPECT_EQ(r.error->text().rfind(file + ":" + std::to_string(line) + ": ", 0), 0u)
      << r.error->text();
}

inline void expect_asf_error(const std::string& text, int line, const std::string& expected) {
  expect_error(parse_asf(text, "t.asf", 0.2), "t.asf", line, expected);
}

inline void expect_amc_error(const std::string& text, int line, const std::string& expected) {
  expect_error(parse_amc(text, "t.amc", small_skeleton()), "t.amc", line, expected);
}

}  // namespace jelly::skeleton::test
