// Outputs of `jelly study effects`: CSV, a Markdown table, a plot of every measure against the
// swept value and a plot of each run over time, both drawn by gnuplot (study_files.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "jelly/body_kind.hpp"
#include "study_effects.hpp"
#include "study_files.hpp"

namespace jelly::cli::study {

namespace {

const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                          "#555555", "#8c564b", "#e377c2", "#17becf", "#bcbd22"};

std::string csv_text(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

/// The swept values as numbers when every one is a number (for a numeric x axis).
std::vector<double> numeric_values(const EffectsResult& r) {
  std::vector<double> xs;
  if (r.options.key.empty()) return xs;
  for (const std::string& v : r.options.values) {
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || !std::isfinite(x)) return {};
    xs.push_back(x);
  }
  return xs;
}

std::string run_label(const EffectsResult& r, const EffectsRow& row) {
  std::string label = std::string(to_string(row.integrator));
  if (!r.options.key.empty()) label += " " + r.options.key + "=" + row.value;
  return label;
}

/// gnuplot's multiplot line for `panels` panels: three columns from five panels on, else two.
std::string multiplot_layout(int panels, const std::string& title) {
  const int columns = panels > 4 ? 3 : panels > 1 ? 2 : 1;
  const int rows = (panels + columns - 1) / columns;
  return multiplot_line(rows, columns, title);
}

/// The kinds' measures that `m` turns on (every one when `all`), in their order.
std::vector<KindMeasure> kinds_on(const Measures& m, bool all = false) {
  std::vector<KindMeasure> on;
  for (const KindMeasure& k : kind_measures())
    if (all || m.has(k.measure->name)) on.push_back(k);
  return on;
}

/// The CSV: one row per run, with the columns of the measures the scene's assignment reports.
std::string effects_csv(const EffectsResult& r) {
  const EffectsOptions& o = r.options;
  const Measures& m = o.measures;
  std::ostringstream csv;
  csv << "scene,key,value,integrator,h,particles,springs,stable,finite,detected_at,"
      << (m.impact ? "contact_time,impact_speed," : "")
      << (m.bounce ? "turn_time,peak_speed_after_impact,com_apex,bounce_height," : "");
  const std::vector<KindMeasure> kinds = kinds_on(m);
  for (const KindMeasure& k : kinds)
    for (const BodyMeasureColumn& c : k.measure->csv) csv << c.header << ',';
  csv << (m.rest ? "rest_time," : "")
      << (m.energy ? "energy_start,energy_end,energy_dissipated,dissipated_fraction," : "")
      << "sim_s,force_evaluations,cg_iterations,wall_s,wall_s_per_sim_s,reason\n";
  for (const EffectsRow& row : r.rows) {
    csv << r.scene_name << ',' << csv_text(o.key) << ',' << csv_text(row.value) << ','
        << to_string(row.integrator) << ',' << num(row.h) << ',' << row.particles << ','
        << row.springs << ',' << (row.stable ? "true" : "false") << ','
        << (row.finite ? "true" : "false") << ',' << num(row.detected_at) << ',';
    if (m.impact) csv << num(row.contact_time) << ',' << num(row.impact_speed) << ',';
    if (m.bounce)
      csv << num(row.turn_time) << ',' << num(row.peak_speed) << ',' << num(row.com_apex) << ','
          << num(row.bounce) << ',';
    for (const KindMeasure& k : kinds)
      for (const BodyMeasureColumn& c : k.measure->csv) csv << num(row.shown(k, c)) << ',';
    if (m.rest) csv << num(row.rest_time) << ',';
    if (m.energy)
      csv << num(row.energy_start) << ',' << num(row.energy_end) << ',' << num(row.dissipated())
          << ',' << num(row.energy_start != 0.0 ? row.dissipated() / row.energy_start : 0.0) << ',';
    csv << num(row.sim_time) << ',' << row.evaluations << ',' << row.cg_iterations << ','
        << num(row.wall) << ',' << num(row.wall_per_sim()) << ',' << csv_text(row.reason) << '\n';
  }
  return csv.str();
}

/// The Markdown table of the runs, under the heading `title`.
std::string effects_markdown(const EffectsResult& r, const std::string& title) {
  const EffectsOptions& o = r.options;
  const Measures& m = o.measures;
  std::ostringstream md;
  md << "### " << title << "\n\n";
  md << "Scene `" << r.scene_name << "`";
  if (!o.key.empty()) {
    md << ", swept `" << o.key << "`";
    if (r.keys.size() > 1 || (r.keys.size() == 1 && r.keys[0] != o.key)) {
      md << " (";
      for (std::size_t i = 0; i < r.keys.size(); ++i)
        md << (i ? ", " : "") << "`" << r.keys[i] << "`";
      md << ")";
    }
  }
  md << "; T = " << num(o.duration) << " s per run; at rest = every particle slower than "
     << num(o.rest_speed) << " m/s from then to the end (at least " << num(o.rest_hold)
     << " s). Wall time is the stepping only (median of " << o.repeats << " run"
     << (o.repeats > 1 ? "s" : "") << "); load average " << r.load_before << " before, "
     << r.load_after << " after (a shared machine). Definitions: docs/parameters.md.\n\n";
  md << "| integrator |" << (o.key.empty() ? "" : " value |") << " h [s] | stable |"
     << (m.impact ? " impact speed [m/s] |" : "")
     << (m.bounce ? " peak speed after [m/s] | bounce [m] |" : "");
  const std::vector<KindMeasure> kinds = kinds_on(m);
  std::string kinds_rule;
  for (const KindMeasure& k : kinds)
    for (const BodyMeasureColumn& c : k.measure->table) {
      md << ' ' << c.header << " |";
      kinds_rule += "---|";
    }
  md << (m.rest ? " at rest from [s] |" : "") << (m.energy ? " energy lost |" : "")
     << " wall s / sim s | force evals / sim s |\n";
  md << "|---|" << (o.key.empty() ? "" : "---|") << "---|---|" << (m.impact ? "---|" : "")
     << (m.bounce ? "---|---|" : "") << kinds_rule << (m.rest ? "---|" : "")
     << (m.energy ? "---|" : "") << "---|---|\n";
  for (const EffectsRow& row : r.rows) {
    std::string stable = row.stable ? "yes" : "**no**";
    if (!row.stable)
      stable += " (" + std::string(row.finite ? "detector" : "blew up") +
                " at t = " + fmt("%.3g", row.detected_at) + " s)";
    md << "| " << to_string(row.integrator) << " |" << (o.key.empty() ? "" : " " + row.value + " |")
       << " " << num(row.h) << " | " << stable << " | ";
    if (m.impact) md << fmt("%.2f", row.impact_speed) << " | ";
    if (m.bounce) md << fmt("%.2f", row.peak_speed) << " | " << fmt("%.3f", row.bounce) << " | ";
    for (const KindMeasure& k : kinds)
      for (const BodyMeasureColumn& c : k.measure->table)
        md << fmt(c.format, row.shown(k, c)) << " | ";
    if (m.rest)
      md << (std::isnan(row.rest_time) ? std::string("never") : fmt("%.2f", row.rest_time))
         << " | ";
    if (m.energy)
      md << fmt("%.0f %%",
                row.energy_start != 0.0 ? 100.0 * row.dissipated() / row.energy_start : 0.0)
         << " | ";
    md << fmt("%.3g", row.wall_per_sim()) << " | "
       << fmt("%.0f", row.sim_time > 0
                          ? static_cast<double>(row.evaluations + row.cg_iterations) / row.sim_time
                          : 0.0)
       << " |\n";
  }
  return md.str();
}

/// How the runs are laid out against the swept value: one block per integrator.
struct SweepLayout {
  std::vector<double> xs;  ///< the swept values when numeric, else none
  bool numeric = false;
  bool logx = false;
  std::size_t per_block = 0;
  std::size_t blocks = 0;
  /// The kinds' measures in the data: the landing ones always (before the rest time), the
  /// others after the label when any of them is on (a study without them keeps the file it had).
  std::vector<KindMeasure> landing, motion;
  /// The data's column of the label (the x tics when the values are not numbers).
  int label_column() const { return 8 + static_cast<int>(landing.size()); }
  /// The data's column of a kind's measure.
  int column(const KindMeasure& k) const {
    const auto at = [&](const std::vector<KindMeasure>& list) {
      return static_cast<int>(
          std::find_if(list.begin(), list.end(),
                       [&](const KindMeasure& l) { return l.measure == k.measure; }) -
          list.begin());
    };
    return k.measure->place == MeasurePlace::kLanding ? 5 + at(landing)
                                                      : label_column() + 1 + at(motion);
  }
};

SweepLayout sweep_layout(const EffectsResult& r) {
  const EffectsOptions& o = r.options;
  SweepLayout l;
  l.xs = numeric_values(r);
  l.numeric = !l.xs.empty();
  l.logx = l.numeric && *std::min_element(l.xs.begin(), l.xs.end()) > 0.0 &&
           *std::max_element(l.xs.begin(), l.xs.end()) >=
               20.0 * *std::min_element(l.xs.begin(), l.xs.end());
  l.per_block = o.key.empty() ? r.rows.size() : o.values.size();
  l.blocks = l.per_block ? r.rows.size() / l.per_block : 0;
  bool motion_on = false;
  for (const KindMeasure& k : kinds_on(o.measures, true))
    if (k.measure->place == MeasurePlace::kLanding) {
      l.landing.push_back(k);
    } else {
      l.motion.push_back(k);
      motion_on = motion_on || o.measures.has(k.measure->name);
    }
  if (!motion_on) l.motion.clear();
  return l;
}

/// The measures against the swept value, one block per integrator (gnuplot's data file).
std::string effects_sweep_dat(const EffectsResult& r, const SweepLayout& l) {
  const EffectsOptions& o = r.options;
  const std::vector<double>& xs = l.xs;
  const bool numeric = l.numeric;
  const std::size_t per_block = l.per_block, blocks = l.blocks;
  std::ostringstream dat;
  const auto columns = [&](const std::vector<KindMeasure>& kinds, const EffectsRow* row) {
    for (const KindMeasure& k : kinds)
      dat << ' '
          << (row ? num(row->shown(k, k.measure->plot)) : std::string(k.measure->plot.header));
  };
  dat << "# x stable peak_speed bounce";
  columns(l.landing, nullptr);
  dat << " rest_time dissipated_% wall_per_sim label";
  columns(l.motion, nullptr);
  dat << '\n';
  for (std::size_t b = 0; b < blocks; ++b) {
    if (b) dat << "\n\n";
    dat << "# "
        << (o.key.empty() ? "runs" : std::string(to_string(r.rows[b * per_block].integrator)))
        << '\n';
    for (std::size_t i = 0; i < per_block; ++i) {
      const EffectsRow& row = r.rows[b * per_block + i];
      const std::string label = o.key.empty() ? std::string(to_string(row.integrator)) : row.value;
      dat << num(numeric ? xs[i] : static_cast<double>(i + 1)) << ' ' << (row.stable ? 1 : 0) << ' '
          << num(row.peak_speed) << ' ' << num(row.bounce);
      columns(l.landing, &row);
      dat << ' ' << num(row.rest_time) << ' '
          << num(row.energy_start != 0.0 ? 100.0 * row.dissipated() / row.energy_start : 0.0) << ' '
          << num(row.wall_per_sim()) << " \"" << label << "\"";
      columns(l.motion, &row);
      dat << '\n';
    }
  }
  return dat.str();
}

/// One panel of the sweep plot: its data column in effects_sweep_dat's file, its y label,
/// whether the study shows it, and its measure of a row (to find a panel without any finite
/// value: gnuplot refuses it).
struct Panel {
  std::string column;
  std::string label;
  bool shown;
  std::function<double(const EffectsRow&)> measure;
};

/// The sweep plot's panels: the measures the scene's assignment reports, then the cost (the
/// last, on a log scale).
std::vector<Panel> sweep_panels(const Measures& m, const SweepLayout& l) {
  std::vector<Panel> panels = {{"3", "peak centre-of-mass speed after the impact [m/s]", m.bounce,
                                [](const EffectsRow& row) { return row.peak_speed; }},
                               {"4", "bounce height of the centre of mass [m]", m.bounce,
                                [](const EffectsRow& row) { return row.bounce; }}};
  for (const KindMeasure& k : kinds_on(m, true))
    panels.push_back({std::to_string(l.column(k)), std::string(k.measure->plot_label),
                      m.has(k.measure->name),
                      [k](const EffectsRow& row) { return row.shown(k, k.measure->plot); }});
  panels.push_back({std::to_string(l.label_column() - 3), "at rest from [s] (none: never)", m.rest,
                    [](const EffectsRow& row) { return row.rest_time; }});
  panels.push_back({std::to_string(l.label_column() - 2), "energy dissipated [% of the start]",
                    m.energy, [](const EffectsRow& row) { return row.dissipated(); }});
  panels.push_back({std::to_string(l.label_column() - 1), "wall time per simulated second [s]",
                    true, [](const EffectsRow& row) { return row.wall_per_sim(); }});
  return panels;
}

/// One sweep plot's panels written into `body` (the gnuplot commands).
class SweepPanels {
 public:
  SweepPanels(const EffectsResult& r, const SweepLayout& l, const std::filesystem::path& dat,
              std::ostringstream& body)
      : r_(r), l_(l), dat_name_(dat.filename().string()), body_(body) {}

  void write(const Panel& panel, bool last) {
    body_ << "set ylabel '" << panel.label << "' font ',9'\n";
    body_ << (last ? "set logscale y\n" : "unset logscale y\n");
    const bool any = std::any_of(r_.rows.begin(), r_.rows.end(), [&](const EffectsRow& row) {
      return std::isfinite(panel.measure(row));
    });
    if (!any) {
      body_ << "set yrange [0:1]\nset label 1 'no run has this measure' at graph 0.5, graph 0.5 "
               "center\n"
            << "plot 1/0 notitle\nunset label 1\nset yrange [*:*]\n";
      return;
    }
    body_ << "plot ";
    bool cross_titled = false;
    for (std::size_t b = 0; b < l_.blocks; ++b) plot_block(panel.column, b, cross_titled);
    body_ << "\n";
  }

 private:
  /// Block b's curve of the data column, and crosses where the detector fired (titled once).
  void plot_block(const std::string& column, std::size_t b, bool& cross_titled) {
    const EffectsOptions& o = r_.options;
    const std::size_t per_block = l_.per_block;
    const std::string name =
        o.key.empty() ? "runs" : std::string(to_string(r_.rows[b * per_block].integrator));
    const char* colour = kColours[b % (sizeof kColours / sizeof *kColours)];
    body_ << (b ? ", \\\n     " : "") << "'" << dat_name_ << "' index " << b
          << " using 1:" << column
          << (l_.numeric ? "" : ":xtic(" + std::to_string(l_.label_column()) + ")")
          << " with linespoints pt 7 ps 0.7 lw 1.5 lc rgb '" << colour << "' title '" << name
          << "' noenhanced";
    const bool unstable = std::any_of(r_.rows.begin() + static_cast<long>(b * per_block),
                                      r_.rows.begin() + static_cast<long>((b + 1) * per_block),
                                      [](const EffectsRow& row) { return !row.stable; });
    if (unstable) {
      body_ << ", \\\n     '" << dat_name_ << "' index " << b << " using 1:($2 == 0 ? $" << column
            << " : 1/0) with points pt 2 ps 1.8 lw 2 lc rgb '" << colour << "' title '"
            << (cross_titled ? "" : "detector fired") << "'";
      cross_titled = true;
    }
  }

  const EffectsResult& r_;
  const SweepLayout& l_;
  const std::string dat_name_;
  std::ostringstream& body_;
};

/// The sweep plot's settings: axes, ranges, grid.
std::string sweep_plot_header(const EffectsResult& r, const SweepLayout& l,
                              const std::filesystem::path& gp) {
  const std::vector<double>& xs = l.xs;
  const bool numeric = l.numeric;
  const std::string xlabel = r.options.key.empty() ? "integrator" : r.options.key;
  std::ostringstream header;
  header << "# Written by `jelly study effects`; run: gnuplot " << gp.filename().string()
         << " (in this folder). Crosses: the stability detector fired in that run.\n"
         << "set datafile missing 'nan'\nset grid\nset key top left font ',9'\nset xlabel '"
         << xlabel << "' noenhanced\nset offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05\n"
         << "set xrange [" << (numeric ? num(*std::min_element(xs.begin(), xs.end())) : "0.5")
         << ":" << (numeric ? num(*std::max_element(xs.begin(), xs.end())) : num(l.per_block + 0.5))
         << "]\n"
         << (l.logx ? "set logscale x\n" : "") << "set pointsize 1.0\n";
  return header.str();
}

/// The gnuplot script of the measures against the swept value (`gp`: its file, `dat`: the data's).
std::string effects_sweep_plot(const EffectsResult& r, const SweepLayout& l,
                               const std::string& title, const std::filesystem::path& gp,
                               const std::filesystem::path& dat, const std::filesystem::path& svg,
                               const std::filesystem::path& png) {
  const std::vector<Panel> panels = sweep_panels(r.options.measures, l);
  std::ostringstream body;
  body << multiplot_layout(static_cast<int>(std::count_if(panels.begin(), panels.end(),
                                                          [](const Panel& p) { return p.shown; })),
                           title);
  SweepPanels writer(r, l, dat, body);
  for (std::size_t p = 0; p < panels.size(); ++p)
    if (panels[p].shown) writer.write(panels[p], p + 1 == panels.size());
  body << "unset multiplot\n";
  return plot_script(sweep_plot_header(r, l, gp), svg.filename().string(), png.filename().string(),
                     body.str(), 1500, 800);
}

/// Each run over time (gnuplot's data file).
std::string effects_time_dat(const EffectsResult& r) {
  std::ostringstream tdat;
  tdat << "# t com_height com_speed volume_ratio max_particle_speed energy\n";
  for (std::size_t i = 0; i < r.series.size(); ++i) {
    const EffectsSeries& s = r.series[i];
    if (i) tdat << "\n\n";
    tdat << "# " << run_label(r, r.rows[i]) << '\n';
    for (std::size_t j = 0; j < s.t.size(); ++j)
      tdat << num(s.t[j]) << ' ' << num(s.com_height[j]) << ' ' << num(s.com_speed[j]) << ' '
           << num(s.volume_ratio[j]) << ' ' << num(s.max_speed[j]) << ' ' << num(s.energy[j])
           << '\n';
  }
  return tdat.str();
}

/// The gnuplot script of each run over time (`gp`: its file, `dat`: the data's).
std::string effects_time_plot(const EffectsResult& r, const std::string& title,
                              const std::filesystem::path& gp, const std::filesystem::path& dat,
                              const std::filesystem::path& svg, const std::filesystem::path& png) {
  const Measures& m = r.options.measures;
  const std::string tdat_name = dat.filename().string();
  // The kinds' series over time (column 4) has the label of the first measure on that has one.
  std::string series_label;
  for (const KindMeasure& k : kinds_on(m))
    if (series_label.empty()) series_label = std::string(k.measure->time_label);
  const std::string tpanels[4][2] = {{"2", "centre-of-mass height [m]"},
                                     {"4", series_label},
                                     {"3", "centre-of-mass speed [m/s]"},
                                     {"6", "total energy [J]"}};
  const bool tshown[4] = {true, !series_label.empty(), true, m.energy};
  std::ostringstream tbody;
  tbody << multiplot_layout(static_cast<int>(std::count(tshown, tshown + 4, true)), title);
  for (int p = 0; p < 4; ++p) {
    if (!tshown[p]) continue;
    tbody << "set ylabel '" << tpanels[p][1] << "'\nplot ";
    for (std::size_t i = 0; i < r.series.size(); ++i)
      tbody << (i ? ", \\\n     " : "") << "'" << tdat_name << "' index " << i
            << " using 1:" << tpanels[p][0] << " with lines lw 1.5 lc rgb '"
            << kColours[i % (sizeof kColours / sizeof *kColours)] << "' title '"
            << run_label(r, r.rows[i]) << "' noenhanced";
    if (r.series.empty()) tbody << "1/0 notitle";
    tbody << "\n";
  }
  tbody << "unset multiplot\n";
  std::ostringstream theader;
  theader
      << "# Written by `jelly study effects`: every run over time; run: gnuplot "
      << gp.filename().string() << " (in this folder).\n"
      << "set datafile missing 'nan'\nset grid\nset key top right font ',8'\nset xlabel 't [s]'\n";
  return plot_script(theader.str(), svg.filename().string(), png.filename().string(), tbody.str(),
                     1300, 800);
}

/// gnuplot's notes without the empty-range ones: a panel with one value (a single run) makes
/// gnuplot widen its range and say so, which is not news.
std::string without_range_notes(const std::string& note) {
  std::istringstream lines(note);
  std::string kept;
  for (std::string line; std::getline(lines, line);)
    if (line.find("empty y range") == std::string::npos &&
        line.find("empty x range") == std::string::npos)
      kept += line + '\n';
  return kept;
}

}  // namespace

std::vector<std::filesystem::path> write_effects(const EffectsResult& r, const std::string& prefix,
                                                 const std::string& title, std::string& note) {
  StudyFiles files(prefix);
  const auto with = [&](const char* suffix) { return files.path(suffix); };
  files.write(".csv", effects_csv(r));
  files.write(".md", effects_markdown(r, title));
  const SweepLayout layout = sweep_layout(r);
  files.write(".dat", effects_sweep_dat(r, layout));
  files.write(".gp", effects_sweep_plot(r, layout, title, with(".gp"), with(".dat"), with(".svg"),
                                        with(".png")));
  files.plot(".gp", ".svg", ".png", note);
  files.write("-time.dat", effects_time_dat(r));
  files.write("-time.gp", effects_time_plot(r, title, with("-time.gp"), with("-time.dat"),
                                            with("-time.svg"), with("-time.png")));
  files.plot("-time.gp", "-time.svg", "-time.png", note);
  note = without_range_notes(note);
  return files.written();
}

}  // namespace jelly::cli::study
