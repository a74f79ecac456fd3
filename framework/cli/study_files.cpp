// Number formatting, file writing and the gnuplot call shared by the `jelly study` outputs.
#include "study_files.hpp"

#include "jelly/process/process.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace jelly::cli::study {

std::string num(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[40];
  for (int p = 6; p <= 17; ++p) {
    std::snprintf(buf, sizeof buf, "%.*g", p, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

std::string fmt(const char* format, double v) {
  if (std::isnan(v)) return "–";
  if (std::isinf(v)) return "∞";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

void write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + p.string());
}

bool run_gnuplot(const std::filesystem::path& script, const std::filesystem::path& svg,
                 const std::filesystem::path& png, std::string& note) {
  namespace fs = std::filesystem;
  const fs::path dir = script.has_parent_path() ? script.parent_path() : fs::path(".");
  fs::remove(svg);
  fs::remove(png);
  // gnuplot in the script's folder (its output names are relative), through the one launcher: an
  // argument vector, no shell. Ten minutes at most: a study's plots take seconds.
  const auto gnuplot = process::find_on_path("gnuplot");
  process::ChildResult run;
  if (gnuplot)
    run = process::run_child({gnuplot->u8string(), script.filename().u8string()},
                             process::trusted_tool_limits(600.0), dir);
  const std::string out = run.out + run.err;
  if (!run.started || run.timed_out || run.exit_code != 0) {
    note +=
        "gnuplot failed or is not installed (tools/install-deps.sh installs gnuplot-nox); the "
        "script " +
        script.string() + " is kept.\n" + out;
    return false;
  }
  note += out;  // warnings
  return true;
}

std::string loadavg() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  if (!(in >> a >> b >> c)) return "unknown";
  return a + " " + b + " " + c;
}

}  // namespace jelly::cli::study
