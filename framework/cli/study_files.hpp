// What the `jelly study` commands share to write their results: number formatting for CSV and
// Markdown, whole-file writes, the output files of one study (its folder, each write, the list of
// what was written), gnuplot scripts and running gnuplot on them in the output folder, and the
// machine load beside timings.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

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

/// The output files of one study, each named by the prefix and a suffix (".csv", "-time.gp"):
/// makes the prefix's folder, writes each file, runs gnuplot on the scripts, and lists in order
/// what it wrote.
class StudyFiles {
 public:
  /// Creates the folder the prefix names (if it names one), so that every file can be written.
  explicit StudyFiles(std::string prefix);
  /// The file `prefix` + `suffix`.
  std::filesystem::path path(const char* suffix) const;
  /// Writes `text` to path(suffix) (write_file) and lists the file.
  void write(const char* suffix, const std::string& text);
  /// Runs gnuplot on path(gp) (run_gnuplot, `note` gets what it says) and lists the images
  /// path(svg) and path(png) that it drew.
  void plot(const char* gp, const char* svg, const char* png, std::string& note);
  /// The files written and drawn so far, in order.
  const std::vector<std::filesystem::path>& written() const { return written_; }

 private:
  std::string prefix_;
  std::vector<std::filesystem::path> written_;
};

/// A gnuplot script that draws `body` (its plot commands) as an SVG named `svg` and, when the
/// installed gnuplot has pngcairo, as a PNG named `png`, both `width` x `height`; `header`
/// (comments and settings) comes first.
std::string plot_script(const std::string& header, const std::string& svg, const std::string& png,
                        const std::string& body, int width, int height);

/// gnuplot's line that starts a `rows` x `columns` multiplot under `title`.
std::string multiplot_line(int rows, int columns, const std::string& title);

/// The machine's load averages (/proc/loadavg: 1, 5 and 15 min), recorded beside wall times so a
/// reader can tell a loaded run; "unknown" where there is no such file (not Linux).
std::string loadavg();

}  // namespace jelly::cli::study
