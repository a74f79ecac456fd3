// The non-ASCII guard in front of toml++ 3.3.0 (jelly/toml_text.hpp). It follows the text as
// toml++ reads it only as far as the guard needs: comments, the four kinds of string, and the
// bare tokens inside which toml++ does not see quotes (a value that does not start with a quote,
// "[" or "{" is scanned up to the next whitespace, ",", "]", "}" or "#").
#include "jelly/toml_text.hpp"

#include <string>
#include <vector>

namespace jelly {
namespace {

class NonAsciiScan {
 public:
  explicit NonAsciiScan(std::string_view text) : text_(text) {}

  std::optional<TextPlace> run() {
    for (i_ = 0; i_ < text_.size(); ++i_) {
      const auto byte = static_cast<unsigned char>(text_[i_]);
      if ((byte & 0xC0) != 0x80) ++column_;  // count code points, as toml++ does
      if (text_[i_] == '\n') {
        new_line();
        continue;
      }
      if (!step(byte)) return TextPlace{line_, column_};
    }
    return std::nullopt;
  }

 private:
  enum class In { Normal, Comment, Basic, Literal, MultiBasic, MultiLiteral };
  enum class Token { None, Key, Value };

  bool starts(std::string_view what) const { return text_.substr(i_, what.size()) == what; }
  bool in_inline_table() const { return !open_.empty() && open_.back() == '{'; }

  void new_line() {
    ++line_;
    column_ = 0;
    if (state_ == In::MultiBasic || state_ == In::MultiLiteral) return;
    state_ = In::Normal;
    token_ = Token::None;
    if (open_.empty() || open_.back() == 'h') {  // a table header ends with its line
      open_.clear();
      key_next_ = true;
    }
  }

  /// One byte that is not a newline; false when it is a non-ASCII byte toml++ may misread.
  bool step(unsigned char byte) {
    switch (state_) {
      case In::Normal: return normal(byte);
      case In::Comment: return true;
      case In::Basic: basic(); return true;
      case In::Literal:
        if (text_[i_] == '\'') state_ = In::Normal;
        return true;
      case In::MultiBasic:
      case In::MultiLiteral: return multi_line(byte);
    }
    return true;
  }

  bool normal(unsigned char byte) {
    const char ch = text_[i_];
    if (byte >= 0x80) return false;
    if (ch == ' ' || ch == '\t' || ch == '\r') {
      token_ = Token::None;
    } else if (ch == '#') {
      state_ = In::Comment;
    } else if (token_ == Token::Value) {
      value_token(ch);
    } else if (ch == '"' || ch == '\'') {
      open_string(ch);
    } else if (ch == '[' || ch == '{') {
      open_bracket(ch);
    } else if (ch == ']' || ch == '}') {
      if (!open_.empty() && !(ch == ']' && starts("]]") && open_.back() == 'h')) open_.pop_back();
      token_ = Token::None;
    } else if (ch == ',') {
      token_ = Token::None;
      key_next_ = in_inline_table();
    } else if (ch == '=') {
      token_ = Token::None;
      key_next_ = false;
    } else if (ch == '.' && token_ == Token::None && key_next_) {
      // a dot between the parts of a dotted key ("a"."b"): still a key
    } else if (token_ == Token::None) {
      token_ = key_next_ ? Token::Key : Token::Value;
    }
    return true;
  }

  /// Inside a bare value toml++ scans on through quotes, brackets, "=" and ".".
  void value_token(char ch) {
    if (ch == ',' || ch == ']' || ch == '}') {
      token_ = Token::None;
      normal(static_cast<unsigned char>(ch));
    }
  }

  void open_string(char quote) {
    const std::string three(3, quote);
    if (starts(three)) {
      state_ = quote == '"' ? In::MultiBasic : In::MultiLiteral;
      i_ += 2;
      column_ += 2;
    } else {
      state_ = quote == '"' ? In::Basic : In::Literal;
    }
    token_ = Token::None;
  }

  void open_bracket(char ch) {
    const bool header = ch == '[' && open_.empty() && key_next_;
    if (header && starts("[[")) {
      ++i_;
      ++column_;
    }
    open_.push_back(header ? 'h' : ch);
    key_next_ = header || ch == '{';
    token_ = Token::None;
  }

  void basic() {
    const char ch = text_[i_];
    if (ch == '\\' && i_ + 1 < text_.size() && text_[i_ + 1] != '\n') {
      ++i_;  // an escaped character (only ASCII ones are valid escapes)
      ++column_;
    } else if (ch == '"') {
      state_ = In::Normal;
    }
  }

  bool multi_line(unsigned char byte) {
    const char ch = text_[i_];
    const char quote = state_ == In::MultiBasic ? '"' : '\'';
    if (trimming_) {  // after a line-ending backslash toml++ asks of each character: whitespace?
      if (byte >= 0x80) return false;
      if (ch != ' ' && ch != '\t' && ch != '\r') trimming_ = false;
    }
    if (state_ == In::MultiBasic && ch == '\\') {
      std::size_t j = i_ + 1;
      while (j < text_.size() && (text_[j] == ' ' || text_[j] == '\t' || text_[j] == '\r')) ++j;
      if (j < text_.size() && text_[j] == '\n') {
        trimming_ = true;
      } else if (i_ + 1 < text_.size()) {
        ++i_;
        ++column_;
      }
    } else if (ch == quote && starts(std::string(3, quote))) {
      // A closing delimiter may be preceded by up to two quotes that belong to the content.
      std::size_t run = 0;
      while (i_ + run < text_.size() && text_[i_ + run] == quote) ++run;
      i_ += run - 1;
      column_ += static_cast<int>(run) - 1;
      state_ = In::Normal;
      token_ = Token::None;
    }
    return true;
  }

  std::string_view text_;
  std::size_t i_ = 0;
  int line_ = 1;
  int column_ = 0;
  In state_ = In::Normal;
  Token token_ = Token::None;
  bool key_next_ = true;    // the next bare token is a key (line start, "{", "," in "{ }")
  bool trimming_ = false;   // between a line-ending backslash and the next non-blank character
  std::vector<char> open_;  // '[' array, '{' inline table, 'h' a [table] header
};

}  // namespace

std::optional<TextPlace> toml_non_ascii_outside_strings(std::string_view text) {
  return NonAsciiScan(text).run();
}

}  // namespace jelly
