// The report's frames: the course scene drawn from the student's recorded positions beside the
// reference's. The student's positions come from the sandboxed runner (outputs with rule
// "frames"); the reference's from running the reference runner here (cached per reference
// runner binary and case); both are drawn by `jelly render --replay` in this trusted process
// tree. Anything missing (no renderer, no reference runner, a render error) becomes a reason the
// report prints, never a grading failure.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "grading/grade.hpp"
#include "inputs/config.hpp"

namespace jelly::grade {

/// One row of the side-by-side table: a time and the two pictures (paths relative to the report
/// folder, empty when that side has no picture at that time).
struct FrameRow {
  double time = 0.0;  ///< [s] as recorded (the first step at or after the requested time)
  std::string yours, reference;
};

struct CourseFrames {
  bool shown = false;              ///< the course scene was run: the report has a frames section
  std::string unavailable;         ///< why there are no frames at all ("" when there are rows)
  std::vector<std::string> notes;  ///< partial gaps ("your run stopped before t = 5 s", ...)
  std::vector<FrameRow> rows;
};

/// Renders the course scene's frames into out_dir/frames/{yours,reference}/; `work` holds the
/// replay files. Never throws: every problem becomes `unavailable` or a note.
CourseFrames render_course_frames(const GradeConfig& config, const GradeReport& report,
                                  const std::filesystem::path& out_dir,
                                  const std::filesystem::path& work);

/// Replay CSV (frame,time,particle,x,y,z; framework/session/include/jelly/session/replay.hpp) of
/// recorded outputs frame_times / frame_positions. Frames with a non-finite number are left out
/// and their times appended to `dropped`. Returns the times of the frames written, in order
/// (frame k of the file is the k-th of them).
std::vector<double> write_replay_csv(const Json& outputs, const std::filesystem::path& path,
                                     std::vector<double>& dropped);

}  // namespace jelly::grade
