// Trajectory recording: per-frame summaries in memory and streaming CSV writers.
#pragma once

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "jelly/world.hpp"

namespace jelly {

/// One recorded frame's summary (the `--summary` CSV columns).
struct FrameSummary {
  double time = 0.0;
  Vec3 com = Vec3::Zero();  ///< centre of mass [m]
  double kinetic = 0.0;     ///< [J]
  double potential = 0.0;   ///< gravitational [J]
  double spring = 0.0;      ///< [J]
  double max_speed = 0.0;   ///< largest particle speed [m/s]
};

/// Computes the summary of state s of world w at time t.
FrameSummary summarize(const World& w, const State& s, double t);

/// Appends CSV rows to a file as frames arrive, so that what was written survives a stopped run.
/// Numbers are written in the shortest form that reads back to the same double.
class CsvWriter {
 public:
  /// Opens (truncates) `path` and writes `header`. Throws std::runtime_error naming the path
  /// when it cannot be opened.
  CsvWriter(const std::filesystem::path& path, const std::string& header);
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  /// Trajectory rows: `frame,time,particle,x,y,z,vx,vy,vz`, one per particle.
  void write_particles(long frame, double time, const State& s);
  /// Summary row: `time,com_x,com_y,com_z,kinetic,potential,spring,max_speed`.
  void write_summary(const FrameSummary& f);
  /// A row of numbers, in the order given (a body kind's own `--summary` row).
  void write_row(const std::vector<double>& values);
  /// A row of numbers and text cells, in the order given (a body kind's row that names something:
  /// a bone of a kind's body). Numbers as write_row writes them; text as given, so it must hold no
  /// comma, quote or line break.
  void write_cells(const std::vector<std::variant<double, std::string>>& cells);
  /// Flushes to the OS.
  void flush();

 private:
  void put(double value);
  void put(long value);
  std::FILE* file_ = nullptr;
  std::string buffer_;
};

inline constexpr const char* kTrajectoryHeader = "frame,time,particle,x,y,z,vx,vy,vz";
inline constexpr const char* kSummaryHeader =
    "time,com_x,com_y,com_z,kinetic,potential,spring,max_speed";

/// 64-bit FNV-1a hash of the bits of a state (determinism tests).
std::uint64_t state_hash(const State& s);

}  // namespace jelly
