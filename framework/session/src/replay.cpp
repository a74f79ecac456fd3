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

/// The columns a replay's header must name, in the order a row's values are kept.
constexpr const char* kColumns[] = {"frame", "time", "particle", "x", "y", "z"};
constexpr int kColumnCount = 6;

/// One replay text read line by line: the header's columns, then the rows, a frame at a time. Each
/// step returns false after keeping the error ("SOURCE:LINE: what").
class ReplayParser {
 public:
  ReplayParser(std::string_view text, std::string_view source_name)
      : in_{std::string(text)}, source_(source_name) {}

  ReplayResult parse() {
    ReplayResult result;
    if (read_header() && read_rows())
      result.replay = std::move(replay_);
    else
      result.error = error_;
    return result;
  }

 private:
  bool fail(long line, const std::string& what) {
    error_ = source_ + ":" + std::to_string(line) + ": " + what;
    return false;
  }

  /// The first line that is not blank: the column of each named field.
  bool read_header() {
    while (std::getline(in_, line_)) {
      ++line_no_;
      const std::vector<std::string> cells = split_csv(line_);
      if (cells == std::vector<std::string>{""}) continue;  // blank line
      return read_columns(cells);
    }
    return fail(line_no_, "empty file (expected a header frame,time,particle,x,y,z and rows)");
  }

  bool read_columns(const std::vector<std::string>& cells) {
    width_ = cells.size();
    for (std::size_t c = 0; c < cells.size(); ++c)
      for (int k = 0; k < kColumnCount; ++k)
        if (cells[c] == kColumns[k]) col_[k] = static_cast<int>(c);
    for (int k = 0; k < kColumnCount; ++k)
      if (col_[k] < 0)
        return fail(line_no_,
                    std::string("the header has no column '") + kColumns[k] +
                        "' (expected frame,time,particle,x,y,z as `jelly run --out` writes)");
    return true;
  }

  bool read_rows() {
    while (std::getline(in_, line_)) {
      ++line_no_;
      const std::vector<std::string> cells = split_csv(line_);
      if (cells == std::vector<std::string>{""}) continue;
      if (!read_row(cells)) return false;
    }
    if (!close_frame()) return false;
    if (replay_.frames.empty()) return fail(line_no_, "no frames (only a header)");
    return true;
  }

  /// One particle's row: it opens a new frame when its frame number changes.
  bool read_row(const std::vector<std::string>& cells) {
    if (cells.size() != width_)
      return fail(line_no_, "expected " + std::to_string(width_) + " values like the header, got " +
                                std::to_string(cells.size()));
    double v[kColumnCount] = {};  // every one read by read_values
    if (!read_values(cells, v)) return false;
    if (v[0] != std::floor(v[0]) || v[2] != std::floor(v[2]) || v[2] < 0)
      return fail(line_no_, "frame and particle must be whole numbers ≥ 0");
    const long f = static_cast<long>(v[0]), p = static_cast<long>(v[2]);
    if ((!open_ || f != frame_) && !open_frame(f, v[1])) return false;
    if (p != static_cast<long>(current_.size()))
      return fail(line_no_, "frame " + std::to_string(f) + ": expected particle " +
                                std::to_string(current_.size()) + ", got " + std::to_string(p) +
                                " (particles in order 0, 1, 2, ...)");
    if (!std::isfinite(v[3]) || !std::isfinite(v[4]) || !std::isfinite(v[5]))
      return fail(line_no_, "particle " + std::to_string(p) + ": position is not finite");
    current_.emplace_back(v[3], v[4], v[5]);
    return true;
  }

  /// The row's value of each named column into v (in kColumns' order).
  bool read_values(const std::vector<std::string>& cells, double (&v)[kColumnCount]) {
    for (int k = 0; k < kColumnCount; ++k)
      if (!to_double(cells[static_cast<std::size_t>(col_[k])], v[k]))
        return fail(line_no_, std::string("column '") + kColumns[k] +
                                  "': expected a number, got '" +
                                  cells[static_cast<std::size_t>(col_[k])] + "'");
    return true;
  }

  /// Ends the open frame and starts frame `f`, which must not have appeared before.
  bool open_frame(long f, double time) {
    if (!close_frame()) return false;
    for (const ReplayFrame& seen : replay_.frames)
      if (seen.frame == f)
        return fail(line_no_, "frame " + std::to_string(f) +
                                  " appears again (a frame's rows must be consecutive)");
    frame_ = f;
    time_ = time;
    open_ = true;
    return true;
  }

  /// Keeps the open frame's particles (as many as the first frame's), if a frame is open.
  bool close_frame() {
    if (!open_) return true;
    if (!replay_.frames.empty() && static_cast<long>(current_.size()) != replay_.particles())
      return fail(line_no_,
                  "frame " + std::to_string(frame_) + " has " + std::to_string(current_.size()) +
                      " particles, the first frame has " + std::to_string(replay_.particles()));
    ReplayFrame f;
    f.frame = frame_;
    f.time = time_;
    f.x.resize(3, static_cast<Eigen::Index>(current_.size()));
    for (std::size_t i = 0; i < current_.size(); ++i)
      f.x.col(static_cast<Eigen::Index>(i)) = current_[i];
    replay_.frames.push_back(std::move(f));
    current_.clear();
    open_ = false;
    return true;
  }

  std::istringstream in_;
  std::string source_;
  std::string line_;
  long line_no_ = 0;
  std::string error_;
  int col_[kColumnCount] = {-1, -1, -1, -1, -1, -1};  // the header's column of each kColumns
  std::size_t width_ = 0;                             // the header's number of columns
  Replay replay_;
  std::vector<Vec3> current_;  // the open frame's positions so far
  long frame_ = 0;             // the open frame's number and time
  double time_ = 0.0;
  bool open_ = false;
};

}  // namespace

ReplayResult parse_replay(std::string_view text, std::string_view source_name) {
  return ReplayParser(text, source_name).parse();
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
