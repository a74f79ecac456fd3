// Lines, tokens and numbers of the ASF and AMC files, shared by their readers (internal).
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "jelly/skeleton/skeleton.hpp"

namespace jelly::skeleton::detail {

/// One line of a file: its 1-based number and its white-space separated tokens (none if blank).
struct Line {
  int number = 0;
  std::vector<std::string_view> tokens;

  bool blank() const { return tokens.empty(); }
  /// Whether the first token starts with `c` ('#' comments, ':' sections and keywords).
  bool starts_with(char c) const { return !tokens.empty() && tokens.front().front() == c; }
};

/// The lines of `text` (LF or CRLF ends), numbered from 1. The views point into `text`.
std::vector<Line> split_lines(std::string_view text);

/// The line number of the end of the file: the last line + 1.
int end_of_file_line(const std::vector<Line>& lines);

/// ASCII lower case (section names, keys and channel tokens are read without regard to case).
std::string lower(std::string_view s);

/// A whole token that is a finite decimal number ([+−]digits[.digits][e[+−]digits]); nullopt for
/// anything else, `nan`, `inf`, hexadecimal and numbers beyond the double range included.
std::optional<double> parse_number(std::string_view token);
/// A whole token that is an optional sign and digits, within the range of int.
std::optional<int> parse_integer(std::string_view token);

/// "'token'" for messages, shortened when long.
std::string quote_token(std::string_view token);
/// The tokens from `first` on, joined by one space, quoted.
std::string quote_rest(const Line& line, std::size_t first);

/// The channel named by a token (any case): tx ty tz rx ry rz, or nullopt.
std::optional<Channel> channel_from_token(std::string_view token);
/// The channel's lower-case name.
const char* channel_name(Channel c);

/// The first error of a reader, thrown inside it and turned into a FileError at its top.
struct ReadFailure : std::runtime_error {
  int line;
  ReadFailure(int line_number, const std::string& message)
      : std::runtime_error(message), line(line_number) {}
};

/// Reads a whole file as bytes; on failure returns nullopt with `why` set.
std::optional<std::string> read_file_text(const std::filesystem::path& path, std::string& why);

}  // namespace jelly::skeleton::detail
