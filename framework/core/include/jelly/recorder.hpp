// Trajectory recording: per-frame summaries in memory and streaming CSV writers.
#pragma once

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
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

/// One recorded frame of a cloth scene (cloth contract decision 12): `cloth` is the cloth's own
/// summary (centre of mass of every cloth particle, pinned ones included; the cloth's kinetic and
/// gravitational energy, measured from y = 0; the spring energy; the cloth's largest speed), with
/// the cloth's lowest y and each sphere's centre and velocity beside it, in scene order.
struct ClothFrameSummary {
  FrameSummary cloth;
  double lowest_y = 0.0;                ///< lowest y of any cloth particle [m]
  std::vector<Vec3> sphere_centers;     ///< [m]
  std::vector<Vec3> sphere_velocities;  ///< [m/s]
};

/// Computes the summary of state s of a cloth world w at time t (decision 12).
ClothFrameSummary summarize_cloth(const World& w, const State& s, double t);

/// The `--summary` header of a cloth scene with `spheres` spheres: the columns of
/// kSummaryHeader, then lowest_y, then sphere<i>_x,_y,_z,_vx,_vy,_vz for each sphere.
std::string cloth_summary_header(int spheres);

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
  /// Cloth summary row: the columns of write_summary, then cloth_summary_header's.
  void write_cloth_summary(const ClothFrameSummary& f);
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
