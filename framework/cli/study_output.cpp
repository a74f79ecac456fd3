// Outputs of `jelly study accuracy`: CSV, Markdown table, and a work-precision plot drawn by
// gnuplot (SVG, and PNG through pngcairo when the installed gnuplot has it).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "study_accuracy.hpp"
#include "study_files.hpp"

namespace jelly::cli::study {

namespace {

/// Largest finite error of stable runs, for the plot's cap (10× above, rounded up to a decade).
double plot_cap(const SweepResult& r) {
  double worst = 0.0;
  for (const RunRow& row : r.rows)
    if (row.stable && std::isfinite(row.error_rms)) worst = std::max(worst, row.error_rms);
  if (!(worst > 0.0)) worst = 1.0;
  return std::pow(10.0, std::ceil(std::log10(worst)) + 1.0);
}

constexpr double kPlotFloor = 1e-16;  // errors below are drawn here (log axes cannot show 0)

const char* colour(IntegratorKind k) {
  switch (k) {
    case IntegratorKind::ExplicitEuler: return "#d62728";
    case IntegratorKind::ImplicitEuler: return "#ff7f0e";
    case IntegratorKind::Midpoint: return "#2ca02c";
    case IntegratorKind::RK4: return "#1f77b4";
    case IntegratorKind::SymplecticEuler: return "#9467bd";
    case IntegratorKind::BackwardEuler: return "#555555";
  }
  return "#000000";
}

/// The CSV: one row per run.
std::string accuracy_csv(const SweepResult& r) {
  std::ostringstream csv;
  csv << "scene,integrator,h,stable,finite,detected_at,error_final,error_rms,wall_s,sim_s,"
         "wall_s_per_sim_s,force_evaluations,cg_iterations,order_final,order_rms,reason\n";
  for (const RunRow& row : r.rows)
    csv << r.scene_name << ',' << to_string(row.integrator) << ',' << num(row.h) << ','
        << (row.stable ? "true" : "false") << ',' << (row.finite ? "true" : "false") << ','
        << num(row.detected_at) << ',' << num(row.error_final) << ',' << num(row.error_rms) << ','
        << num(row.wall) << ',' << num(row.sim_time) << ',' << num(row.wall_per_sim()) << ','
        << row.evaluations << ',' << row.cg_iterations << ',' << num(row.order_final) << ','
        << num(row.order_rms) << ",\"" << row.reason << "\"\n";
  return csv.str();
}

/// The smallest positive RMS error of a stable run (infinity when there is none).
double smallest_stable_error(const SweepResult& r) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const RunRow& row : r.rows)
    if (row.stable && row.error_rms > 0.0) smallest = std::min(smallest, row.error_rms);
  return smallest;
}

/// The Markdown text above the table: the scene, the reference run, the norms and the automatic
/// steps.
std::string accuracy_intro(const SweepResult& r, const std::string& title) {
  const SweepOptions& o = r.options;
  const double smallest = smallest_stable_error(r);
  std::ostringstream md;
  md << "### " << title << "\n\n";
  md << "Scene `" << r.scene_name << "`: " << r.particles << " particles, " << r.springs
     << " springs, " << r.terrains << " terrains; T = " << num(o.duration)
     << " s, errors sampled every " << num(o.sample_dt) << " s.";
  if (r.first_collision_time >= 0)
    md << " First collision response in the reference run at t = "
       << fmt("%.4f", r.first_collision_time) << " s.";
  else
    md << " No collision happened in the reference run (the trajectory is smooth).";
  md << "\n\nReference: RK4 at h_ref = " << num(r.reference.h) << " s ("
     << fmt("%.3g", r.reference.wall) << " s of wall time).";
  if (r.reference.checked)
    md << " RK4 at h_ref/2 differs from it by " << fmt("%.2e", r.reference.check_rms)
       << " m (RMS) and " << fmt("%.2e", r.reference.check_final)
       << " m (max at T); the smallest stable RMS error measured is " << fmt("%.2e", smallest)
       << " m (ratio " << fmt("%.2g", r.reference.check_rms / smallest) << ").";
  md << "\n\nError norms: `error_rms` = RMS over particles and sample times of |x − x_ref|; "
        "`error_final` = largest |x − x_ref| over particles at T. `order` = log(e_coarse/e_fine) / "
        "log(h_coarse/h_fine) from the next coarser step (RMS error). Wall time is the stepping "
        "only (minimum of "
     << o.repeats << " run" << (o.repeats > 1 ? "s" : "") << "); load average " << r.load_before
     << " before, " << r.load_after << " after (a shared 2-core machine).\n\n";
  md << "Automatic step (`jelly run --auto-dt`: half the estimated limit, at most the scene's dt):";
  for (std::size_t i = 0; i < r.auto_steps.size() && i < o.integrators.size(); ++i)
    md << (i ? "; " : " ") << to_string(o.integrators[i]) << " " << r.auto_steps[i];
  md << ".\n\n";
  return md.str();
}

/// The Markdown table: one line per run.
std::string accuracy_table(const SweepResult& r) {
  std::ostringstream md;
  md << "| integrator | h [s] | stable | RMS error [m] | final error [m] | order (RMS) | "
        "wall s / sim s | force evals | CG iters |\n";
  md << "|---|---|---|---|---|---|---|---|---|\n";
  for (const RunRow& row : r.rows) {
    std::string stable = row.stable ? "yes" : "**no**";
    if (!row.stable)
      stable += " (" + std::string(row.finite ? "detector" : "blew up") +
                " at t = " + fmt("%.3g", row.detected_at) + " s)";
    md << "| " << to_string(row.integrator) << " | " << num(row.h) << " | " << stable << " | "
       << fmt("%.3e", row.error_rms) << " | " << fmt("%.3e", row.error_final) << " | "
       << fmt("%.2f", row.order_rms) << " | " << fmt("%.3g", row.wall_per_sim()) << " | "
       << row.evaluations << " | " << (row.cg_iterations ? std::to_string(row.cg_iterations) : "")
       << " |\n";
  }
  return md.str();
}

/// One block of the plot data: the stable or the unstable runs of one integrator.
struct PlotBlock {
  IntegratorKind kind;
  bool stable;
  int index;  ///< gnuplot's index of the block in the data file
};

/// The plot data: per integrator, a block of stable runs then a block of unstable ones (an empty
/// block holds one line of NaNs); errors clipped to [kPlotFloor, cap]. `blocks` gets the blocks
/// that hold runs.
std::string accuracy_dat(const SweepResult& r, double cap, std::vector<PlotBlock>& blocks) {
  std::ostringstream dat;
  dat << "# h error_rms(plotted) wall_s_per_sim_s work(evaluations+cg) error_final(plotted)\n";
  int index = 0;
  for (IntegratorKind kind : r.options.integrators)
    for (bool stable : {true, false}) {
      std::ostringstream b;
      int n = 0;
      for (const RunRow& row : r.rows) {
        if (row.integrator != kind || row.stable != stable) continue;
        const auto clip = [&](double e) {
          return std::isfinite(e) ? std::clamp(e, kPlotFloor, cap) : cap;
        };
        b << num(row.h) << ' ' << num(clip(row.error_rms)) << ' ' << num(row.wall_per_sim()) << ' '
          << (row.evaluations + row.cg_iterations) << ' ' << num(clip(row.error_final)) << '\n';
        ++n;
      }
      if (index > 0) dat << "\n\n";
      dat << "# " << to_string(kind) << (stable ? " stable" : " unstable") << '\n' << b.str();
      if (n == 0) dat << "nan nan nan nan nan\n";
      if (n > 0) blocks.push_back({kind, stable, index});
      ++index;
    }
  return dat.str();
}

/// The plot commands: three panels sharing the error axis (SciML's convention, x = error), each
/// drawing every block of `dat_name` with a dashed line at the cap.
std::string accuracy_panels(const std::string& title, const std::vector<PlotBlock>& blocks,
                            double cap, const std::string& dat_name) {
  const std::string panels[3] = {"wall time per simulated second [s]",
                                 "force evaluations (+ CG mat-vec products)", "step h [s]"};
  const int ycol[3] = {3, 4, 1};
  std::ostringstream g;
  g << multiplot_line(1, 3, title);
  for (int p = 0; p < 3; ++p) {
    g << "set ylabel '" << panels[p] << "'\n";
    g << "set arrow 1 from " << num(cap) << ", graph 0 to " << num(cap)
      << ", graph 1 nohead dashtype 2 lc rgb '#999999'\n";
    g << "plot ";
    bool first = true;
    for (const PlotBlock& b : blocks) {
      if (!first) g << ", \\\n     ";
      first = false;
      g << "'" << dat_name << "' index " << b.index << " using 2:" << ycol[p];
      if (b.stable)
        g << " with linespoints pt 7 ps 0.6 lw 1.5 lc rgb '" << colour(b.kind) << "' title '"
          << to_string(b.kind) << "' noenhanced";
      else
        g << " with points pt 2 ps 1.6 lw 2 lc rgb '" << colour(b.kind) << "' title '"
          << to_string(b.kind) << " unstable' noenhanced";
    }
    if (first) g << "1/0 notitle";
    g << "\nunset arrow 1\n";
  }
  g << "unset multiplot\n";
  return g.str();
}

/// The gnuplot script of the work-precision plot (`files`: where the script, data and images go).
std::string accuracy_plot(const std::string& title, const std::vector<PlotBlock>& blocks,
                          double cap, const StudyFiles& files) {
  std::ostringstream header;
  header << "# Work-precision plot written by `jelly study accuracy`; run: gnuplot "
         << files.path(".gp").filename().string() << " (in this folder)\n";
  header << "set datafile missing 'nan'\nset logscale xy\nset grid\nset key top right font ',9'\n"
            "set format x '10^{%L}'\nset format y '10^{%L}'\nset xlabel 'RMS position error [m]'\n"
            "set pointsize 1.0\n";
  const std::string body =
      accuracy_panels(title, blocks, cap, files.path(".dat").filename().string());
  std::ostringstream footer;
  footer << "# Unstable runs (the §8 detector fired, or the state blew up) are crosses; "
         << "errors above " << num(cap)
         << " m (and non-finite ones) are drawn at that cap (dashed line); errors below "
         << num(kPlotFloor) << " m at that floor.\n";
  return plot_script(header.str(), files.path(".svg").filename().string(),
                     files.path(".png").filename().string(), body, 1500, 520) +
         footer.str();
}

}  // namespace

std::vector<std::filesystem::path> write_outputs(const SweepResult& r, const std::string& prefix,
                                                 const std::string& title, std::string& note) {
  StudyFiles files(prefix);
  files.write(".csv", accuracy_csv(r));
  files.write(".md", accuracy_intro(r, title) + accuracy_table(r));
  const double cap = plot_cap(r);
  std::vector<PlotBlock> blocks;
  files.write(".dat", accuracy_dat(r, cap, blocks));
  files.write(".gp", accuracy_plot(title, blocks, cap, files));
  files.plot(".gp", ".svg", ".png", note);
  return files.written();
}

}  // namespace jelly::cli::study
