// The AMC reader (kinematics contract §2, §11.8): a header, then frames of `name v1 v2 …` lines.
#include <string>
#include <vector>

#include "jelly/skeleton/skeleton_files.hpp"
#include "skeleton_file_text.hpp"

namespace jelly::skeleton {

namespace detail {

namespace {

// Header lines (`#` and `:`) before the first frame: :DEGREES, :FULLY-SPECIFIED and other
// keywords are accepted, :RADIANS is not. Returns the index of the first other line.
std::size_t read_amc_header(const std::vector<Line>& lines, std::vector<FileNote>& notes) {
  std::size_t i = 0;
  for (; i < lines.size(); ++i) {
    const Line& line = lines[i];
    if (line.blank() || line.starts_with('#')) continue;
    if (!line.starts_with(':')) break;
    const std::string keyword = lower(line.tokens[0]);
    if (keyword == ":radians")
      throw ReadFailure(line.number, ":RADIANS is not supported; expected :DEGREES");
    if (keyword != ":degrees" && keyword != ":fully-specified") {
      notes.push_back({line.number, "header keyword " + quote_token(line.tokens[0]) + " ignored"});
    }
  }
  return i;
}

bool is_frame_line(const Line& line) {
  return line.tokens.size() == 1 && parse_integer(line.tokens[0]).has_value();
}

// Sets the channels of one bone from a `name v1 v2 …` line.
void read_bone_line(const Line& line, const Skeleton& skeleton, int bone, Posture& posture) {
  const Bone& b = skeleton.bones[bone];
  if (b.channels.empty()) {
    throw ReadFailure(line.number,
                      "bone " + quote_token(b.name) + " has no channels; expected no line for it");
  }
  if (line.tokens.size() != b.channels.size() + 1) {
    throw ReadFailure(line.number, "bone " + quote_token(b.name) + ": expected " +
                                       std::to_string(b.channels.size()) +
                                       " numbers (its channels), got " +
                                       std::to_string(line.tokens.size() - 1));
  }
  for (std::size_t k = 0; k < b.channels.size(); ++k) {
    const auto v = parse_number(line.tokens[k + 1]);
    if (!v) {
      throw ReadFailure(line.number, "bone " + quote_token(b.name) +
                                         ": expected a finite number for " +
                                         channel_name(b.channels[k]) + ", got " +
                                         quote_token(line.tokens[k + 1]));
    }
    const int c = static_cast<int>(b.channels[k]);
    if (c < 3) {
      posture.root_translation[c] = skeleton.scale * *v;
    } else {
      posture.angles[bone][c - 3] = *v;
    }
  }
}

// One frame's bone lines, from `i` up to the next frame line; returns the index after them.
std::size_t read_frame(const std::vector<Line>& lines, std::size_t i, const Skeleton& skeleton,
                       Posture& posture) {
  std::vector<int> seen_on(skeleton.bones.size(), 0);
  for (; i < lines.size() && !is_frame_line(lines[i]); ++i) {
    const Line& line = lines[i];
    if (line.blank()) continue;
    if (line.starts_with('#') || line.starts_with(':')) {
      throw ReadFailure(line.number, "expected a bone line or a frame number, got " +
                                         quote_rest(line, 0) +
                                         " (header lines come before the first frame)");
    }
    const auto bone = skeleton.find(line.tokens[0]);
    if (!bone)
      throw ReadFailure(line.number, "unknown bone " + quote_token(line.tokens[0]) +
                                         "; expected a bone of the skeleton");
    if (seen_on[*bone] != 0) {
      throw ReadFailure(line.number, "bone " + quote_token(line.tokens[0]) +
                                         " given twice in one frame (line " +
                                         std::to_string(seen_on[*bone]) + ")");
    }
    seen_on[*bone] = line.number;
    read_bone_line(line, skeleton, *bone, posture);
  }
  return i;
}

Motion read_frames(const std::vector<Line>& lines, std::size_t i, const Skeleton& skeleton) {
  Motion motion;
  for (; i < lines.size() && lines[i].blank(); ++i) {
  }
  if (i == lines.size())
    throw ReadFailure(end_of_file_line(lines), "the file has no frame; expected at least one");
  if (!is_frame_line(lines[i])) {
    throw ReadFailure(lines[i].number,
                      "expected a frame number (a whole number), got " + quote_rest(lines[i], 0));
  }
  long long expected = *parse_integer(lines[i].tokens[0]);
  motion.first_frame_number = static_cast<int>(expected);
  while (i < lines.size()) {
    const int number = *parse_integer(lines[i].tokens[0]);
    if (number != expected) {
      throw ReadFailure(lines[i].number, "frame number " + std::to_string(number) + ": expected " +
                                             std::to_string(expected) +
                                             " (frame numbers increase by 1)");
    }
    motion.frames.push_back(Posture::zero(skeleton.bones.size()));
    i = read_frame(lines, i + 1, skeleton, motion.frames.back());
    ++expected;
  }
  return motion;
}

}  // namespace

}  // namespace detail

MotionResult parse_amc(std::string_view text, std::string_view file_name,
                       const Skeleton& skeleton) {
  using namespace detail;
  MotionResult result;
  const std::vector<Line> lines = split_lines(text);
  try {
    const std::size_t first = read_amc_header(lines, result.notes);
    result.motion = read_frames(lines, first, skeleton);
  } catch (const ReadFailure& failure) {
    result.error = FileError{std::string(file_name), failure.line, failure.what()};
  }
  return result;
}

MotionResult read_amc(const std::filesystem::path& path, const Skeleton& skeleton) {
  std::string why;
  const auto text = detail::read_file_text(path, why);
  if (!text) {
    MotionResult result;
    result.error = FileError{path.string(), 0, why};
    return result;
  }
  return parse_amc(*text, path.string(), skeleton);
}

}  // namespace jelly::skeleton
