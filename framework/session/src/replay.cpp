#include "jelly/session/replay.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace jelly::session {

namespace {

std::vector<std::string> split_csv(std::string_view line) {
  std::vector<std::string> out;
  std::string cell;
  for (char c : line) {
    if (c == ',') {
      out.push_back(cell);
      cell.clear();
    } else if (c != '\r' && c != ' ' && c != '\t') {
      cell += c;
    }
  }
  out.push_back(cell);
  return out;
}

bool to_double(const std::string& s, double& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end && *end == '\0';
}

}  // namespace

ReplayResult parse_replay(std::string_view text, std::string_view source_name) {
  ReplayResult result;
  const std::string source(source_name);
  const auto fail = [&](long line, const std::string& what) {
    result.error = source + ":" + std::to_string(line) + ": " + what;
    return result;
  };
  std::istringstream in{std::string(text)};
  std::string line;
  long line_no = 0;
  // Header: the column of each named field.
  const char* names[] = {"frame", "time", "particle", "x", "y", "z"};
  int col[6] = {-1, -1, -1, -1, -1, -1};
  std::size_t width = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (split_csv(line) == std::vector<std::string>{""}) continue;  // blank line
    const std::vector<std::string> cells = split_csv(line);
    width = cells.size();
    for (std::size_t c = 0; c < cells.size(); ++c)
      for (int k = 0; k < 6; ++k)
        if (cells[c] == names[k]) col[k] = static_cast<int>(c);
    for (int k = 0; k < 6; ++k)
      if (col[k] < 0)
        return fail(line_no,
                    std::string("the header has no column '") + names[k] +
                        "' (expected frame,time,particle,x,y,z as `jelly run --out` writes)");
    break;
  }
  if (width == 0)
    return fail(line_no, "empty file (expected a header frame,time,particle,x,y,z and rows)");

  Replay replay;
  std::vector<Vec3> current;
  long frame = 0;
  double time = 0.0;
  bool open = false;
  const auto close_frame = [&](long at_line) -> bool {
    if (!open) return true;
    if (!replay.frames.empty() && static_cast<long>(current.size()) != replay.particles()) {
      fail(at_line, "frame " + std::to_string(frame) + " has " + std::to_string(current.size()) +
                        " particles, the first frame has " + std::to_string(replay.particles()));
      return false;
    }
    ReplayFrame f;
    f.frame = frame;
    f.time = time;
    f.x.resize(3, static_cast<Eigen::Index>(current.size()));
    for (std::size_t i = 0; i < current.size(); ++i)
      f.x.col(static_cast<Eigen::Index>(i)) = current[i];
    replay.frames.push_back(std::move(f));
    current.clear();
    open = false;
    return true;
  };
  while (std::getline(in, line)) {
    ++line_no;
    const std::vector<std::string> cells = split_csv(line);
    if (cells == std::vector<std::string>{""}) continue;
    if (cells.size() != width)
      return fail(line_no, "expected " + std::to_string(width) + " values like the header, got " +
                               std::to_string(cells.size()));
    double v[6];
    for (int k = 0; k < 6; ++k)
      if (!to_double(cells[static_cast<std::size_t>(col[k])], v[k]))
        return fail(line_no, std::string("column '") + names[k] + "': expected a number, got '" +
                                 cells[static_cast<std::size_t>(col[k])] + "'");
    if (v[0] != std::floor(v[0]) || v[2] != std::floor(v[2]) || v[2] < 0)
      return fail(line_no, "frame and particle must be whole numbers ≥ 0");
    const long f = static_cast<long>(v[0]), p = static_cast<long>(v[2]);
    if (!open || f != frame) {
      if (!close_frame(line_no)) return result;
      for (const ReplayFrame& seen : replay.frames)
        if (seen.frame == f)
          return fail(line_no, "frame " + std::to_string(f) +
                                   " appears again (a frame's rows must be consecutive)");
      frame = f;
      time = v[1];
      open = true;
    }
    if (p != static_cast<long>(current.size()))
      return fail(line_no, "frame " + std::to_string(f) + ": expected particle " +
                               std::to_string(current.size()) + ", got " + std::to_string(p) +
                               " (particles in order 0, 1, 2, ...)");
    if (!std::isfinite(v[3]) || !std::isfinite(v[4]) || !std::isfinite(v[5]))
      return fail(line_no, "particle " + std::to_string(p) + ": position is not finite");
    current.emplace_back(v[3], v[4], v[5]);
  }
  if (!close_frame(line_no)) return result;
  if (replay.frames.empty()) return fail(line_no, "no frames (only a header)");
  result.replay = std::move(replay);
  return result;
}

ReplayResult load_replay(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    ReplayResult r;
    r.error = path.string() + ": cannot open the replay file";
    return r;
  }
  std::ostringstream s;
  s << in.rdbuf();
  return parse_replay(s.str(), path.string());
}

}  // namespace jelly::session
