// The ASF reader (kinematics contract §1, §11.1–§11.7): its sections and the :root section.
#include <set>
#include <utility>

#include "asf_draft.hpp"
#include "jelly/skeleton/skeleton_files.hpp"

namespace jelly::skeleton {

namespace detail {

const Line* AsfCursor::peek() {
  while (at_ < lines_.size() && (lines_[at_].blank() || lines_[at_].starts_with('#'))) ++at_;
  return at_ < lines_.size() ? &lines_[at_] : nullptr;
}

namespace {

// Consumes the lines of a section whose content is ignored (:version, :name, :documentation).
void skip_section_body(AsfCursor& cursor) {
  while (!cursor.at_section_end()) cursor.advance();
}

// :units: `angle` must be deg; `mass` and `length` are ignored; other keys are noted.
void read_units_section(AsfCursor& cursor, AsfDraft& draft) {
  for (; !cursor.at_section_end(); cursor.advance()) {
    const Line& line = *cursor.peek();
    const std::string key = lower(line.tokens[0]);
    if (key == "angle") {
      const std::string unit = line.tokens.size() == 2 ? lower(line.tokens[1]) : "";
      if (unit == "rad")
        throw ReadFailure(line.number,
                          ":units: angle 'rad' is not supported; expected 'angle deg'");
      if (unit != "deg")
        throw ReadFailure(line.number, ":units: expected 'angle deg', got " + quote_rest(line, 1));
    } else if (key != "mass" && key != "length") {
      draft.notes.push_back(
          {line.number, ":units: unknown key " + quote_token(line.tokens[0]) + " skipped"});
    }
  }
}

// `order`: a permutation of TX TY TZ RX RY RZ (any case).
std::vector<Channel> read_root_order(const Line& line) {
  std::vector<Channel> order;
  for (std::size_t i = 1; i < line.tokens.size(); ++i) {
    const auto c = channel_from_token(line.tokens[i]);
    bool repeated = false;
    for (Channel o : order) repeated = repeated || (c && o == *c);
    if (!c || repeated) break;
    order.push_back(*c);
  }
  if (order.size() != 6 || line.tokens.size() != 7) {
    throw ReadFailure(
        line.number,
        ":root: order must list the six channels TX TY TZ RX RY RZ, each once, in any "
        "order; got " +
            quote_rest(line, 1));
  }
  return order;
}

// `position` and `orientation` must be three numbers equal to 0; `axis` must be XYZ.
void check_root_value(const Line& line, const std::string& key) {
  if (key == "axis") {
    if (line.tokens.size() != 2 || lower(line.tokens[1]) != "xyz") {
      throw ReadFailure(line.number, ":root: axis must be XYZ; got " + quote_rest(line, 1));
    }
    return;
  }
  bool zeros = line.tokens.size() == 4;
  for (std::size_t i = 1; zeros && i < 4; ++i) {
    const auto v = parse_number(line.tokens[i]);
    zeros = v && *v == 0.0;
  }
  if (!zeros)
    throw ReadFailure(line.number, ":root: " + key + " must be 0 0 0; got " + quote_rest(line, 1));
}

}  // namespace

void read_root_section(AsfCursor& cursor, AsfDraft& draft, int section_line) {
  std::set<std::string> seen;
  draft.root.name = "root";
  for (; !cursor.at_section_end(); cursor.advance()) {
    const Line& line = *cursor.peek();
    const std::string key = lower(line.tokens[0]);
    const bool known = key == "order" || key == "axis" || key == "position" || key == "orientation";
    if (!known) {
      draft.notes.push_back(
          {line.number, ":root: unknown key " + quote_token(line.tokens[0]) + " skipped"});
      continue;
    }
    if (!seen.insert(key).second)
      throw ReadFailure(line.number, ":root: " + key + " given twice; expected it once");
    if (key == "order") {
      draft.root.channels = read_root_order(line);
    } else {
      check_root_value(line, key);
    }
  }
  if (seen.count("order") == 0) {
    throw ReadFailure(section_line,
                      ":root has no 'order'; expected 'order TX TY TZ RX RY RZ' (any order)");
  }
  draft.has_root = true;
}

namespace {

// Reads one section from its ':' line on; `seen` holds the known sections already read.
void read_section(AsfCursor& cursor, AsfDraft& draft, std::set<std::string>& seen) {
  const Line& head = *cursor.peek();
  const std::string name = lower(head.tokens[0]);
  const int line = head.number;
  cursor.advance();
  static const std::set<std::string> kKnown = {
      ":version", ":name", ":units", ":documentation", ":root", ":bonedata", ":hierarchy"};
  if (kKnown.count(name) == 0) {
    draft.notes.push_back({line, "unknown section " + quote_token(head.tokens[0]) + " skipped"});
    skip_section_body(cursor);
    return;
  }
  if (!seen.insert(name).second)
    throw ReadFailure(line, "section " + name + " given twice; expected it once");
  if (name == ":units") {
    read_units_section(cursor, draft);
  } else if (name == ":root") {
    read_root_section(cursor, draft, line);
  } else if (name == ":bonedata") {
    read_bonedata_section(cursor, draft);
  } else if (name == ":hierarchy") {
    read_hierarchy_section(cursor, draft);
  } else {
    skip_section_body(cursor);
  }
}

Skeleton build_skeleton(AsfDraft& draft, int end_of_file, double scale) {
  if (!draft.has_root)
    throw ReadFailure(end_of_file, "the file has no :root section; expected one");
  Skeleton skeleton;
  skeleton.scale = scale;
  skeleton.bones.reserve(draft.bones.size() + 1);
  skeleton.bones.push_back(std::move(draft.root));
  for (Bone& b : draft.bones) skeleton.bones.push_back(std::move(b));
  resolve_hierarchy(skeleton.bones, draft, end_of_file);
  derive_bone_data(skeleton);
  return skeleton;
}

}  // namespace

}  // namespace detail

SkeletonResult parse_asf(std::string_view text, std::string_view file_name, double scale) {
  using namespace detail;
  SkeletonResult result;
  const std::vector<Line> lines = split_lines(text);
  AsfDraft draft;
  try {
    if (!(scale > 0.0 && scale < 1e300))
      throw ReadFailure(0, "the scale must be a positive number");
    AsfCursor cursor(lines);
    std::set<std::string> seen;
    while (const Line* line = cursor.peek()) {
      if (!line->starts_with(':')) {
        throw ReadFailure(
            line->number,
            "expected a section line such as ':root' or ':bonedata', got " + quote_rest(*line, 0));
      }
      read_section(cursor, draft, seen);
    }
    result.skeleton = build_skeleton(draft, end_of_file_line(lines), scale);
  } catch (const ReadFailure& failure) {
    result.error = FileError{std::string(file_name), failure.line, failure.what()};
  }
  result.notes = std::move(draft.notes);
  return result;
}

SkeletonResult read_asf(const std::filesystem::path& path, double scale) {
  std::string why;
  const auto text = detail::read_file_text(path, why);
  if (!text) {
    SkeletonResult result;
    result.error = FileError{path.string(), 0, why};
    return result;
  }
  return parse_asf(*text, path.string(), scale);
}

}  // namespace jelly::skeleton
