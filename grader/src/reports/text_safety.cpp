#include "reports/text_safety.hpp"

#include <algorithm>

namespace jelly::grade {

namespace {

const char* const kReplacement = "\xEF\xBF\xBD";  // U+FFFD

// Decodes the character at s[i] into `cp` and returns its length; when the bytes there are not a
// well-formed character, returns 0 and sets `skip` to the length of the maximal ill-formed subpart
// (Unicode's "U+FFFD substitution of maximal subparts": a truncated character is one U+FFFD).
std::size_t decode(const std::string& s, std::size_t i, unsigned& cp, std::size_t& skip) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned c = b(i);
  skip = 1;
  if (c < 0x80) {
    cp = c;
    return 1;
  }
  std::size_t n;
  unsigned lo = 0x80, hi = 0xBF;  // the allowed range of the second byte
  if (c >= 0xC2 && c <= 0xDF)
    n = 2, cp = c & 0x1F;
  else if (c >= 0xE0 && c <= 0xEF)
    n = 3, cp = c & 0x0F, lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
  else if (c >= 0xF0 && c <= 0xF4)
    n = 4, cp = c & 0x07, lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
  else
    return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if (i + k >= s.size()) return 0;
    const unsigned x = b(i + k);
    if (k == 1 ? (x < lo || x > hi) : (x & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (x & 0x3F);
    skip = k + 1;
  }
  return n;
}

}  // namespace

void append_utf8(std::string& out, unsigned cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

std::string valid_utf8(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    unsigned cp;
    std::size_t skip;
    const std::size_t n = decode(s, i, cp, skip);
    if (n == 0) {
      out += kReplacement;
      i += skip;
    } else {
      out.append(s, i, n);
      i += n;
    }
  }
  return out;
}

std::string safe_text(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    unsigned cp;
    std::size_t skip;
    const std::size_t n = decode(s, i, cp, skip);
    if (n == 0) {
      out += kReplacement;
      i += skip;
      continue;
    }
    if (cp == '\r' && i + 1 < s.size() && s[i + 1] == '\n') {
      // "\r\n": the newline alone
    } else if (cp == '\n' || cp == '\t') {
      out += static_cast<char>(cp);
    } else if (cp < 0x20) {
      append_utf8(out, 0x2400 + cp);  // Control Pictures: ␀ … ␟ (␛ for ESC)
    } else if (cp == 0x7F) {
      append_utf8(out, 0x2421);  // ␡
    } else if ((cp >= 0x80 && cp <= 0x9F) || (cp >= 0x202A && cp <= 0x202E) ||
               (cp >= 0x2066 && cp <= 0x2069)) {
      out += kReplacement;
    } else {
      out.append(s, i, n);
    }
    i += n;
  }
  return out;
}

std::string cut_utf8(const std::string& s, std::size_t max_bytes) {
  if (s.size() <= max_bytes) return s;
  std::size_t end = max_bytes;
  // Back to the start of the character that would be cut (continuation bytes are 10xxxxxx).
  while (end > 0 && (static_cast<unsigned char>(s[end]) & 0xC0) == 0x80) --end;
  return s.substr(0, end);
}

std::string safe_excerpt(const std::string& s, std::size_t max_bytes) {
  const std::string safe = safe_text(s);
  if (safe.size() <= max_bytes) return safe;
  return cut_utf8(safe, max_bytes) + "…";
}

std::string html_escape(const std::string& s) {
  std::string o;
  o.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      case '\'': o += "&#39;"; break;
      default:
        // Controls are made visible by safe_text; any left are not valid in XML 1.0.
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t')
          o += "\xEF\xBF\xBD";
        else
          o += c;
    }
  }
  return o;
}

std::string markdown_inline(const std::string& s) {
  // The characters that start emphasis, code, links, images, tables, headings or raw HTML
  // anywhere in a line; a list marker only at the start.
  static const std::string punct = "\\`*_[]|~!#";
  std::string o;
  o.reserve(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (i == 0 && (c == '-' || c == '+' || c == '>'))
      o += std::string("\\") + c;
    else if (c == '<')
      o += "&lt;";
    else if (c == '&')
      o += "&amp;";
    else if (c == '\n' || c == '\r')
      o += ' ';
    else if (punct.find(c) != std::string::npos)
      o += std::string("\\") + c;
    else
      o += c;
  }
  return o;
}

std::string markdown_code_block(const std::string& s) {
  std::size_t longest = 0, run = 0;
  for (char c : s) {
    run = c == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  const std::string fence(std::max<std::size_t>(3, longest + 1), '`');
  std::string body = s;
  if (!body.empty() && body.back() != '\n') body += '\n';
  return fence + "text\n" + body + fence + "\n";
}

namespace {
const char* const kGutter = "\xE2\x94\x82 ";  // "│ "
}

std::string set_apart(const std::string& s, const std::string& indent) {
  std::string out = indent + kGutter;
  for (std::size_t i = 0; i < s.size(); ++i) {
    out += s[i];
    if (s[i] == '\n' && i + 1 < s.size()) out += indent + kGutter;
  }
  if (out.back() != '\n') out += '\n';
  return out;
}

std::string hanging(const std::string& s, const std::string& indent) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    out += s[i];
    if (s[i] == '\n' && i + 1 < s.size()) out += indent + kGutter;
  }
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

std::string one_line(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '\n' ? std::string("\xE2\x90\xA4") : std::string(1, c);
  return out;
}

}  // namespace jelly::grade
