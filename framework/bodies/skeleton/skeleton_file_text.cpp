// Lines, tokens and numbers of the ASF and AMC files (internal; skeleton_file_text.hpp).
#include "skeleton_file_text.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "jelly/number_text.hpp"
#include "jelly/skeleton/skeleton_files.hpp"

namespace jelly::skeleton {

std::string FileError::text() const {
  std::string out = file.empty() ? std::string("<skeleton file>") : file;
  if (line > 0) out += ':' + std::to_string(line);
  return out + ": " + message;
}

}  // namespace jelly::skeleton

namespace jelly::skeleton::detail {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::vector<std::string_view> split_tokens(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

// The characters of a decimal number in the form parse_number accepts, checked before conversion
// so that from_chars' `inf`, `nan` and hexadecimal forms are refused.
bool looks_decimal(std::string_view t) {
  std::size_t i = (!t.empty() && (t[0] == '+' || t[0] == '-')) ? 1 : 0;
  std::size_t digits = 0;
  while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i, ++digits;
  if (i < t.size() && t[i] == '.') {
    for (++i; i < t.size() && t[i] >= '0' && t[i] <= '9'; ++i) ++digits;
  }
  if (digits == 0) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    const std::size_t exponent_start = i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
    if (i == exponent_start) return false;
  }
  return i == t.size();
}

}  // namespace

std::vector<Line> split_lines(std::string_view text) {
  std::vector<Line> lines;
  int number = 1;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    lines.push_back({number++, split_tokens(text.substr(start, end - start))});
    start = end + 1;
  }
  return lines;
}

int end_of_file_line(const std::vector<Line>& lines) {
  return lines.empty() ? 1 : lines.back().number + 1;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return out;
}

std::optional<double> parse_number(std::string_view t) {
  if (!looks_decimal(t)) return std::nullopt;
  const auto v = read_double(t);
  if (!v || !std::isfinite(*v)) return std::nullopt;
  return v;
}

std::optional<int> parse_integer(std::string_view t) {
  const auto v = read_integer(t);
  if (!v || *v < std::numeric_limits<int>::min() || *v > std::numeric_limits<int>::max())
    return std::nullopt;
  return static_cast<int>(*v);
}

std::string quote_token(std::string_view token) {
  std::string s = "'";
  s.append(token.substr(0, 60));
  if (token.size() > 60) s += "...";
  return s + "'";
}

std::string quote_rest(const Line& line, std::size_t first) {
  std::string s;
  for (std::size_t i = first; i < line.tokens.size(); ++i) {
    if (!s.empty()) s += ' ';
    s.append(line.tokens[i]);
  }
  return quote_token(s);
}

std::optional<Channel> channel_from_token(std::string_view token) {
  const std::string t = lower(token);
  constexpr Channel kAll[] = {Channel::tx, Channel::ty, Channel::tz,
                              Channel::rx, Channel::ry, Channel::rz};
  for (Channel c : kAll) {
    if (t == channel_name(c)) return c;
  }
  return std::nullopt;
}

const char* channel_name(Channel c) {
  switch (c) {
    case Channel::tx: return "tx";
    case Channel::ty: return "ty";
    case Channel::tz: return "tz";
    case Channel::rx: return "rx";
    case Channel::ry: return "ry";
    default: return "rz";
  }
}

std::optional<std::string> read_file_text(const std::filesystem::path& path, std::string& why) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) {
    why = "cannot read the file: no such file";
    return std::nullopt;
  }
  if (std::filesystem::is_directory(status)) {
    why = "is a directory; expected a file";
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in || in.bad()) {
    why = "cannot read the file";
    return std::nullopt;
  }
  return text.str();
}

}  // namespace jelly::skeleton::detail
