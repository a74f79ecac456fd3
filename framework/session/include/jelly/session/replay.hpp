// Recorded particle positions to draw instead of simulating (`jelly render --replay FILE`): the
// trajectory CSV that `jelly run --out` writes, `frame,time,particle,x,y,z[,vx,vy,vz]`, one row
// per particle per frame. The grader writes the same format for the course scene's frames, so a
// run that happened elsewhere (the sandboxed grading runner) is drawn without running its code.
// A frame may go on, after the state's particles, with points a body kind records there (its
// view module's replay points, which `jelly render --replay` places).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "jelly/types.hpp"

namespace jelly::session {

/// One recorded frame: the positions of every particle at one time.
struct ReplayFrame {
  long frame = 0;     ///< the file's frame number
  double time = 0.0;  ///< [s]
  Vec3Array x;        ///< 3×N positions [m], column i = particle i
};

/// Every frame of a replay file, in file order; every frame has the same particle count.
struct Replay {
  std::vector<ReplayFrame> frames;
  long particles() const { return frames.empty() ? 0 : static_cast<long>(frames.front().x.cols()); }
};

struct ReplayResult {
  std::optional<Replay> replay;
  std::string error;  ///< "FILE:LINE: what is wrong, what was expected" when replay is empty
  explicit operator bool() const { return replay.has_value(); }
};

/// Parses replay CSV text. The header names the columns (any order; at least frame, time,
/// particle, x, y, z; others such as vx are ignored). A frame's rows are consecutive, its
/// particles numbered 0..N−1 in order, and every frame has the same N. Never throws.
ReplayResult parse_replay(std::string_view text, std::string_view source_name);
/// Reads and parses a replay file.
ReplayResult load_replay(const std::filesystem::path& path);

}  // namespace jelly::session
