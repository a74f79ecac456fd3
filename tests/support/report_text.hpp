// Reading a grading report as a student's viewer does (tests of issue 28: student text passes for
// the grader's): which lines start where the report's own do, and what Markdown renders outside
// its fenced code blocks.
#pragma once

#include <algorithm>
#include <sstream>
#include <string>

namespace jelly::testing {

/// How many lines of `text` start with `prefix`.
inline int lines_starting(const std::string& text, const std::string& prefix) {
  std::istringstream in(text);
  int n = 0;
  for (std::string line; std::getline(in, line);) n += line.rfind(prefix, 0) == 0;
  return n;
}

/// The Markdown `md` outside its fenced code blocks (CommonMark: a fence of n >= 3 backticks,
/// indented at most three spaces, is closed only by a line of at least n backticks alone).
inline std::string outside_code_blocks(const std::string& md) {
  std::istringstream in(md);
  std::string out;
  std::size_t fence = 0;
  for (std::string line; std::getline(in, line);) {
    const std::size_t indent = std::min(line.find_first_not_of(' '), line.size());
    const std::string rest = indent <= 3 ? line.substr(indent) : std::string();
    const std::size_t ticks = std::min(rest.find_first_not_of('`'), rest.size());
    if (fence == 0 && ticks >= 3) {
      fence = ticks;
    } else if (fence == 0) {
      out += line + "\n";
    } else if (ticks >= fence && rest.find_first_not_of("` ") == std::string::npos) {
      fence = 0;
    }
  }
  return out;
}

}  // namespace jelly::testing
