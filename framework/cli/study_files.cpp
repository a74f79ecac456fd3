// Number formatting, file writing and the gnuplot call shared by the `jelly study` outputs.
#include "study_files.hpp"

#include "jelly/process/process.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>

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

StudyFiles::StudyFiles(std::string prefix) : prefix_(std::move(prefix)) {
  const std::filesystem::path base(prefix_);
  if (base.has_parent_path()) std::filesystem::create_directories(base.parent_path());
}

std::filesystem::path StudyFiles::path(const char* suffix) const {
  return std::filesystem::path(prefix_ + suffix);
}

void StudyFiles::write(const char* suffix, const std::string& text) {
  write_file(path(suffix), text);
  written_.push_back(path(suffix));
}

void StudyFiles::plot(const char* gp, const char* svg, const char* png, std::string& note) {
  if (!run_gnuplot(path(gp), path(svg), path(png), note)) return;
  if (std::filesystem::exists(path(svg))) written_.push_back(path(svg));
  if (std::filesystem::exists(path(png))) written_.push_back(path(png));
}

std::string plot_script(const std::string& header, const std::string& svg, const std::string& png,
                        const std::string& body, int width, int height) {
  std::ostringstream gp;
  gp << header;
  gp << "set terminal svg size " << width << "," << height
     << " dynamic enhanced font 'sans,11' background '#ffffff'\nset output '" << svg << "'\n"
     << body;
  gp << "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n  set terminal pngcairo size " << width
     << "," << height << " enhanced font 'sans,10'\n  set output '" << png << "'\n";
  std::istringstream lines(body);
  for (std::string line; std::getline(lines, line);) gp << "  " << line << '\n';
  gp << "}\nset output\n";
  return gp.str();
}

std::string multiplot_line(int rows, int columns, const std::string& title) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "set multiplot layout %d,%d title \"%s\" noenhanced font ',12'\n",
                rows, columns, title.c_str());
  return buf;
}

std::string loadavg() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  if (!(in >> a >> b >> c)) return "unknown";
  return a + " " + b + " " + c;
}

}  // namespace jelly::cli::study
