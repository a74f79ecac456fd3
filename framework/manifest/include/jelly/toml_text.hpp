// A guard in front of toml++ 3.3.0 (Debian 12's), shared by every reader of a user's TOML file.
//
// TOML allows non-ASCII characters only inside strings and comments. toml++ 3.3.0 reaches
// TOML_UNREACHABLE (undefined behaviour; upstream issues #190 and #295, fixed after 3.3.0) when it
// asks whether some of them (U+00A1–U+0499, much of U+2C8E–U+3087) are whitespace: outside a
// string, after a line-ending backslash in a multi-line string, and anywhere in the up to 127
// characters it scans after the start of a bare value ("+", "1", "inf"...), quotes included.
// Text where toml++ could meet one there is refused before it is parsed, with the place.
#pragma once

#include <optional>
#include <string_view>

namespace jelly {

/// A place in a text: 1-based line, and column in code points (as toml++ counts them).
struct TextPlace {
  int line = 0;
  int column = 0;
};

/// The first non-ASCII character of `text` that toml++ 3.3.0 would read outside a string or a
/// comment (or as whitespace), or nothing when every one is safely inside a string or comment.
/// Valid TOML keeps its strings and comments; what is refused is never valid TOML, except a
/// non-ASCII character right after a line-ending backslash in a """ string.
std::optional<TextPlace> toml_non_ascii_outside_strings(std::string_view text);

/// The message for it, the same from every reader.
inline constexpr std::string_view kTomlNonAsciiMessage =
    "malformed TOML: a non-ASCII character outside a string or comment (TOML allows them only "
    "inside \"strings\" and # comments)";

}  // namespace jelly
