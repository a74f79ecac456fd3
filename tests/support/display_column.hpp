// The display column where a text starts in a line of the terminal tables, counted by the tests
// without the project's own helper (jelly/cli_common/text_table.hpp), so that both can be wrong
// only in different ways.
#pragma once

#include <cstddef>
#include <string>

namespace jelly::test {

/// The display column of `what` in `line`: the UTF-8 code points before it (every text the tables
/// print is one column a character); npos when `line` does not hold it.
inline std::size_t column_of(const std::string& line, const std::string& what) {
  const std::size_t at = line.find(what);
  if (at == std::string::npos) return std::string::npos;
  std::size_t n = 0;
  for (std::size_t i = 0; i < at; ++i) n += (static_cast<unsigned char>(line[i]) & 0xC0) != 0x80;
  return n;
}

}  // namespace jelly::test
