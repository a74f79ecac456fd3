#include "reports/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace jelly::grade {

namespace {
std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}
std::string esc(const std::string& s) {
  std::string o;
  for (char c : s)
    o += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return o;
}
}  // namespace

std::string svg_plot(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                     const std::vector<Series>& series, int width, int height) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const Series& s : series)
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
        x0 = std::min(x0, s.x[i]), x1 = std::max(x1, s.x[i]), y0 = std::min(y0, s.y[i]),
        y1 = std::max(y1, s.y[i]);
  if (!(x1 > x0)) x0 = 0, x1 = 1;
  if (!(y1 > y0)) y0 -= 1, y1 += 1;
  const double pad = 0.05 * (y1 - y0);
  y0 -= pad, y1 += pad;
  const int L = 60, R = 20, T = 30, B = 45;
  const double pw = width - L - R, ph = height - T - B;
  auto X = [&](double x) { return L + (x - x0) / (x1 - x0) * pw; };
  auto Y = [&](double y) { return T + (1.0 - (y - y0) / (y1 - y0)) * ph; };
  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) +
                  "\" height=\"" + std::to_string(height) +
                  "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  s += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s += "<text x=\"" + std::to_string(width / 2) +
       "\" y=\"18\" text-anchor=\"middle\" font-size=\"14\">" + esc(title) + "</text>\n";
  s += "<rect x=\"" + num(L) + "\" y=\"" + num(T) + "\" width=\"" + num(pw) + "\" height=\"" +
       num(ph) + "\" fill=\"none\" stroke=\"#444\"/>\n";
  for (int k = 0; k <= 5; ++k) {
    const double xv = x0 + (x1 - x0) * k / 5.0, yv = y0 + (y1 - y0) * k / 5.0;
    s += "<text x=\"" + num(X(xv)) + "\" y=\"" + num(T + ph + 16) + "\" text-anchor=\"middle\">" +
         num(xv) + "</text>\n";
    s += "<text x=\"" + num(L - 6) + "\" y=\"" + num(Y(yv) + 4) + "\" text-anchor=\"end\">" +
         num(yv) + "</text>\n";
    s += "<line x1=\"" + num(L) + "\" x2=\"" + num(L + pw) + "\" y1=\"" + num(Y(yv)) + "\" y2=\"" +
         num(Y(yv)) + "\" stroke=\"#eee\"/>\n";
  }
  s += "<text x=\"" + num(L + pw / 2) + "\" y=\"" + num(height - 8) + "\" text-anchor=\"middle\">" +
       esc(xlabel) + "</text>\n";
  s += "<text x=\"14\" y=\"" + num(T + ph / 2) +
       "\" text-anchor=\"middle\" transform=\"rotate(-90 14 " + num(T + ph / 2) + ")\">" +
       esc(ylabel) + "</text>\n";
  int li = 0;
  for (const Series& se : series) {
    std::string pts;
    for (std::size_t i = 0; i < std::min(se.x.size(), se.y.size()); ++i)
      if (std::isfinite(se.x[i]) && std::isfinite(se.y[i]))
        pts += num(X(se.x[i])) + "," + num(Y(se.y[i])) + " ";
    s += "<polyline fill=\"none\" stroke=\"" + se.color + "\" stroke-width=\"2\"" +
         (se.dashed ? " stroke-dasharray=\"6 4\"" : "") + " points=\"" + pts + "\"/>\n";
    const double ly = T + 14 + 16 * li++;
    s += "<line x1=\"" + num(L + pw - 150) + "\" x2=\"" + num(L + pw - 125) + "\" y1=\"" +
         num(ly - 4) + "\" y2=\"" + num(ly - 4) + "\" stroke=\"" + se.color +
         "\" stroke-width=\"2\"" + (se.dashed ? " stroke-dasharray=\"6 4\"" : "") + "/>\n";
    s += "<text x=\"" + num(L + pw - 120) + "\" y=\"" + num(ly) + "\">" + esc(se.label) +
         "</text>\n";
  }
  s += "</svg>\n";
  return s;
}

}  // namespace jelly::grade
