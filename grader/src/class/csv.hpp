// The batch's class files (scores.csv): RFC 4180 fields, written whole or not at all.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace jelly::grade {

/// One CSV field (RFC 4180): quoted when it holds a comma, a double quote, CR or LF, or starts or
/// ends with a space; quotes doubled. `text` fields (names, messages, never numbers) that a
/// spreadsheet would read as a formula (starting with = + - @, tab or CR) get a leading
/// apostrophe, the spreadsheets' own "this is text" mark.
std::string csv_field(const std::string& value, bool text = true);

/// A CSV record: the fields joined by commas, ended by CRLF (RFC 4180).
std::string csv_row(const std::vector<std::string>& fields);

/// Writes `text` to `path` through a temporary file in the same folder and a rename, so that a
/// reader never sees a half-written file. Throws std::runtime_error naming the file on failure.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace jelly::grade
