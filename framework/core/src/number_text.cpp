// Locale-independent numbers from text (jelly/number_text.hpp).
#include "jelly/number_text.hpp"

#include <charconv>
#include <string>
#if defined(_LIBCPP_VERSION) && !defined(__cpp_lib_to_chars)
#include <locale>
#include <sstream>
#endif

namespace jelly {

namespace {

// `token` without its one leading '+', or nullopt when nothing is left or a second sign follows.
std::optional<std::string_view> unsigned_part(std::string_view token) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty() || token.front() == '+') return std::nullopt;
  return token;
}

}  // namespace

std::optional<double> read_double(std::string_view token) {
  const auto t = unsigned_part(token);
  if (!t) return std::nullopt;
  double v = 0.0;
#if defined(_LIBCPP_VERSION) && !defined(__cpp_lib_to_chars)
  // libc++ before LLVM 20 (Apple's Xcode, Debian 12's libc++) has no from_chars for double: read
  // it with the classic "C" locale (correctly rounded there too), the same number of characters.
  std::istringstream in{std::string(*t)};
  in.imbue(std::locale::classic());
  in >> std::noskipws >> v;
  if (in.fail() || in.peek() != std::char_traits<char>::eof()) return std::nullopt;
#else
  const auto res = std::from_chars(t->data(), t->data() + t->size(), v);
  if (res.ec != std::errc() || res.ptr != t->data() + t->size()) return std::nullopt;
#endif
  return v;
}

std::optional<long long> read_integer(std::string_view token) {
  const auto t = unsigned_part(token);
  if (!t) return std::nullopt;
  long long v = 0;
  const auto res = std::from_chars(t->data(), t->data() + t->size(), v);
  if (res.ec != std::errc() || res.ptr != t->data() + t->size()) return std::nullopt;
  return v;
}

}  // namespace jelly
