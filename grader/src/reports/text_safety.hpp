// Text a submission controls (what its tests print, its messages, its file and folder names) made
// safe to show: valid UTF-8, cut on a character boundary, no terminal controls; and escaped for the
// format it goes into (HTML, Markdown). Every report shows student text only through these.
#pragma once

#include <cstddef>
#include <string>

namespace jelly::grade {

/// Appends the code point `cp` (at most U+10FFFF) to `out` in UTF-8.
void append_utf8(std::string& out, unsigned cp);

/// `s` as valid UTF-8: every byte that does not start a well-formed character (invalid lead bytes,
/// truncated or overlong sequences, UTF-16 surrogates, code points above U+10FFFF) becomes U+FFFD.
std::string valid_utf8(const std::string& s);

/// `s` as valid UTF-8 without controls a terminal or a browser would act on: NUL, ESC and the
/// other C0 controls except newline and tab become their visible Control Pictures (U+2400 +
/// code: "␀", "␛"), DEL "␡", the C1 controls (U+0080–U+009F, e.g. the one-character CSI) and the
/// bidirectional overrides (U+202A–U+202E, U+2066–U+2069) U+FFFD; "\r\n" becomes "\n".
std::string safe_text(const std::string& s);

/// At most `max_bytes` bytes of the valid UTF-8 `s`, never cutting a character in two.
std::string cut_utf8(const std::string& s, std::size_t max_bytes);

/// safe_text of the first `max_bytes` bytes of `s` (cut on a character boundary), with "…" when
/// something was left out.
std::string safe_excerpt(const std::string& s, std::size_t max_bytes);

/// For HTML text and attribute values: & < > " ' as entities.
std::string html_escape(const std::string& s);

/// For Markdown inline text: the characters that start emphasis, code, links, images, tables or
/// headings are backslash-escaped (and a list or quote marker at the start), < and & become
/// entities (no raw HTML), line breaks become spaces.
std::string markdown_inline(const std::string& s);

/// A Markdown fenced code block holding `s` verbatim: the fence is longer than any run of
/// backticks in `s`, so nothing in it can end the block.
std::string markdown_code_block(const std::string& s);

/// Student text (what a test printed, the compiler's messages) set apart in a plain-text report
/// (the terminal, Gradescope, PrairieLearn, JUnit): every line after `indent` and "│ ", so that
/// no line of it starts where the report's own lines do ("Total: …" at the left edge).
std::string set_apart(const std::string& s, const std::string& indent);

/// A message whose first line follows a label on the report's line: every further line after
/// `indent` and "│ " (the text after a line break is the student's, or the grader's table).
std::string hanging(const std::string& s, const std::string& indent);

/// `s` on one line (a name in a heading): each line break as "␤".
std::string one_line(const std::string& s);

}  // namespace jelly::grade
