// Tables in a terminal, for every program of the project (jelly's params, check and probe, the
// grader's summary): columns sized to their widest cell and padded by display width, so that
// a title with an en dash (three bytes, one column) lines up with one without.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace jelly::cli {

/// The columns a terminal gives the code point `cp`: 0 for combining marks, zero-width spaces and
/// joiners and variation selectors; 2 for East Asian wide and full-width characters and the
/// emoji blocks; 1 otherwise. A short table of the ranges, enough for the texts we print.
inline int codepoint_width(char32_t cp) {
  struct Range {
    char32_t lo, hi;
  };
  static constexpr Range kZero[] = {{0x0300, 0x036F}, {0x0483, 0x0489}, {0x0591, 0x05BD},
                                    {0x1AB0, 0x1AFF}, {0x1DC0, 0x1DFF}, {0x200B, 0x200F},
                                    {0x2060, 0x2064}, {0x20D0, 0x20FF}, {0xFE00, 0xFE0F},
                                    {0xFE20, 0xFE2F}, {0xFEFF, 0xFEFF}};
  static constexpr Range kWide[] = {{0x1100, 0x115F},   {0x2E80, 0x303E},   {0x3041, 0x33FF},
                                    {0x3400, 0x4DBF},   {0x4E00, 0x9FFF},   {0xA000, 0xA4CF},
                                    {0xAC00, 0xD7A3},   {0xF900, 0xFAFF},   {0xFE30, 0xFE4F},
                                    {0xFF00, 0xFF60},   {0xFFE0, 0xFFE6},   {0x1F300, 0x1F64F},
                                    {0x1F900, 0x1F9FF}, {0x20000, 0x2FFFD}, {0x30000, 0x3FFFD}};
  const auto in = [cp](const auto& ranges) {
    return std::any_of(std::begin(ranges), std::end(ranges),
                       [cp](const Range& r) { return cp >= r.lo && cp <= r.hi; });
  };
  if (in(kZero)) return 0;
  return in(kWide) ? 2 : 1;
}

/// The columns `text` takes in a terminal: its UTF-8 code points by codepoint_width. A byte that
/// does not start a well-formed character counts one column (a terminal shows one U+FFFD).
inline std::size_t display_width(std::string_view text) {
  std::size_t width = 0;
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned lead = byte(i);
    const std::size_t n = lead < 0x80                    ? 1
                          : lead >= 0xF0 && lead <= 0xF4 ? 4
                          : lead >= 0xE0 && lead <= 0xEF ? 3
                          : lead >= 0xC2 && lead <= 0xDF ? 2
                                                         : 0;
    char32_t cp = n == 1 ? lead : lead & (0x7F >> n);
    bool ok = n > 0 && i + n <= text.size();
    for (std::size_t k = 1; ok && k < n; ++k) {
      ok = (byte(i + k) & 0xC0) == 0x80;
      cp = (cp << 6) | (byte(i + k) & 0x3F);
    }
    width += ok ? static_cast<std::size_t>(codepoint_width(cp)) : 1;
    i += ok ? n : 1;
  }
  return width;
}

/// `text` and spaces up to `width` display columns (as is when it is that wide or wider).
inline std::string pad_right(std::string_view text, std::size_t width) {
  const std::size_t w = display_width(text);
  return std::string(text) + std::string(w < width ? width - w : 0, ' ');
}

/// Spaces and `text`, `width` display columns in all (right-aligned).
inline std::string pad_left(std::string_view text, std::size_t width) {
  const std::size_t w = display_width(text);
  return std::string(w < width ? width - w : 0, ' ') + std::string(text);
}

/// A table of text cells: every column as wide as its widest cell (by display width), cells
/// left-aligned unless align_right names their column, the last cell of a row never padded.
class TextTable {
 public:
  /// `gap`: what separates two columns.
  explicit TextTable(std::string gap = "  ") : gap_(std::move(gap)) {}

  void add_row(std::vector<std::string> cells) { rows_.push_back(std::move(cells)); }
  void align_right(std::size_t column) {
    if (right_.size() <= column) right_.resize(column + 1, false);
    right_[column] = true;
  }
  std::size_t size() const { return rows_.size(); }

  /// Row `i`, its columns padded, without a line break.
  std::string row(std::size_t i) const {
    const std::vector<std::size_t> widths = column_widths();
    const std::vector<std::string>& cells = rows_.at(i);
    std::string out;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const bool last = c + 1 == cells.size();
      const bool right = c < right_.size() && right_[c];
      if (c > 0) out += gap_;
      out += right  ? pad_left(cells[c], widths[c])
             : last ? cells[c]
                    : pad_right(cells[c], widths[c]);
    }
    return out;
  }

  /// Every row, each after `indent` and ending in a line break.
  std::string str(std::string_view indent = {}) const {
    std::string out;
    for (std::size_t i = 0; i < rows_.size(); ++i) out += std::string(indent) + row(i) + "\n";
    return out;
  }

 private:
  std::vector<std::size_t> column_widths() const {
    std::vector<std::size_t> widths;
    for (const std::vector<std::string>& cells : rows_) {
      if (widths.size() < cells.size()) widths.resize(cells.size(), 0);
      for (std::size_t c = 0; c < cells.size(); ++c)
        widths[c] = std::max(widths[c], display_width(cells[c]));
    }
    return widths;
  }

  std::string gap_;
  std::vector<std::vector<std::string>> rows_;
  std::vector<bool> right_;
};

}  // namespace jelly::cli
