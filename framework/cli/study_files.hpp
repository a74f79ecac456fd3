// What the `jelly study` commands share to write their results: number formatting for CSV and
// Markdown, whole-file writes, the machine load beside timings, and running gnuplot on a script in
// the output folder.
#pragma once

#include <filesystem>
#include <string>

namespace jelly::cli::study {

/// Shortest text that reads back to the same double; "nan"/"inf" as such (CSV, plot data).
std::string num(double v);
/// printf-formatted for tables; "–" for NaN and "∞" for infinities.
std::string fmt(const char* format, double v);
/// Writes `text` to `p` (binary); throws std::runtime_error naming the file when it cannot.
void write_file(const std::filesystem::path& p, const std::string& text);

/// Runs gnuplot on `script` in its own folder (so relative names in it work), after removing the
/// images it will draw, `svg` and `png`. Returns true when gnuplot ran; `note` gets its warnings,
/// or says that it failed or is missing (the script is kept so the plot can be made later).
bool run_gnuplot(const std::filesystem::path& script, const std::filesystem::path& svg,
                 const std::filesystem::path& png, std::string& note);

/// The machine's load averages (/proc/loadavg: 1, 5 and 15 min), recorded beside wall times so a
/// reader can tell a loaded run; "unknown" where there is no such file (not Linux).
std::string loadavg();

}  // namespace jelly::cli::study
