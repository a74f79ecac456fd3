// The ASF's :bonedata section: `begin … end` blocks, one bone each (kinematics contract §1,
// §11.5, §11.6).
#include <map>
#include <string>

#include "asf_draft.hpp"

namespace jelly::skeleton::detail {

namespace {

// A bone block while it is read: the bone and the line of every key given.
struct BlockDraft {
  Bone bone;
  std::map<std::string, int> key_lines;
  int limits_line = 0;
  bool in_limits = false;  // the previous key line was `limits` (its pairs may continue)
};

std::string bone_label(const BlockDraft& block) {
  return block.bone.name.empty() ? std::string("bone block")
                                 : "bone " + quote_token(block.bone.name);
}

Vec3 read_three_numbers(const Line& line, const std::string& what) {
  Vec3 v;
  bool ok = line.tokens.size() == 4;
  for (int i = 0; ok && i < 3; ++i) {
    const auto x = parse_number(line.tokens[i + 1]);
    ok = x.has_value();
    if (ok) v[i] = *x;
  }
  if (!ok)
    throw ReadFailure(line.number, what + ": expected three numbers, got " + quote_rest(line, 1));
  return v;
}

void read_id(const Line& line, const AsfDraft& draft) {
  const auto id = line.tokens.size() == 2 ? parse_integer(line.tokens[1]) : std::nullopt;
  const int expected = static_cast<int>(draft.bones.size()) + 1;
  if (!id || *id != expected) {
    throw ReadFailure(line.number, "id: expected " + std::to_string(expected) +
                                       " (bones are numbered 1, 2, … in file order), got " +
                                       quote_rest(line, 1));
  }
}

void read_name(const Line& line, const AsfDraft& draft, Bone& bone) {
  if (line.tokens.size() != 2)
    throw ReadFailure(line.number, "name: expected one name, got " + quote_rest(line, 1));
  const std::string name(line.tokens[1]);
  if (name == "root")
    throw ReadFailure(line.number, "name: 'root' is the root's name; expected another bone name");
  for (const Bone& b : draft.bones) {
    if (b.name == name)
      throw ReadFailure(line.number, "name: " + quote_token(name) + " is already a bone's name");
  }
  bone.name = name;
}

void read_direction(const Line& line, Bone& bone) {
  bone.direction = read_three_numbers(line, "direction");
  if (bone.direction.isZero(0.0))
    throw ReadFailure(line.number, "direction: expected a non-zero (unit) vector, got 0 0 0");
}

void read_length(const Line& line, Bone& bone) {
  const auto v = line.tokens.size() == 2 ? parse_number(line.tokens[1]) : std::nullopt;
  if (!v || *v < 0.0)
    throw ReadFailure(line.number, "length: expected one number ≥ 0, got " + quote_rest(line, 1));
  bone.length = *v;
}

void read_axis(const Line& line, Bone& bone) {
  if (line.tokens.size() == 5 && lower(line.tokens[4]) != "xyz") {
    throw ReadFailure(line.number, "axis: the order " + quote_token(line.tokens[4]) +
                                       " is not supported; expected XYZ");
  }
  bool ok = line.tokens.size() == 5;
  for (int i = 0; ok && i < 3; ++i) {
    const auto x = parse_number(line.tokens[i + 1]);
    ok = x.has_value();
    if (ok) bone.axis[i] = *x;
  }
  if (!ok)
    throw ReadFailure(line.number,
                      "axis: expected 'axis ax ay az XYZ' (degrees), got " + quote_rest(line, 1));
}

void read_dof(const Line& line, Bone& bone) {
  if (line.tokens.size() < 2)
    throw ReadFailure(line.number, "dof: expected one to three of rx ry rz, got none");
  for (std::size_t i = 1; i < line.tokens.size(); ++i) {
    const std::string t = lower(line.tokens[i]);
    const auto c = channel_from_token(t);
    if (t == "tx" || t == "ty" || t == "tz" || t == "l") {
      throw ReadFailure(line.number,
                        "dof: " + quote_token(line.tokens[i]) +
                            " is not supported on a bone other than root; expected rx, ry or rz");
    }
    if (!c)
      throw ReadFailure(line.number,
                        "dof: expected rx, ry or rz, got " + quote_token(line.tokens[i]));
    for (Channel o : bone.channels) {
      if (o == *c)
        throw ReadFailure(line.number, "dof: " + quote_token(line.tokens[i]) +
                                           " given twice; expected each channel once");
    }
    bone.channels.push_back(*c);
  }
}

// The `(lo hi)` pairs of a `limits` line (from token `first`) or of a line that continues it.
void read_limit_pairs(const Line& line, std::size_t first, Bone& bone) {
  std::string text;
  for (std::size_t i = first; i < line.tokens.size(); ++i) text.append(line.tokens[i]).append(" ");
  std::string spaced;
  for (char c : text)
    spaced += (c == '(' || c == ')') ? std::string(" ") + c + " " : std::string(1, c);
  const std::vector<Line> split = split_lines(spaced);
  const std::vector<std::string_view> t =
      split.empty() ? std::vector<std::string_view>{} : split[0].tokens;
  const std::string expected =
      "limits: expected '(lo hi)' pairs of numbers with lo ≤ hi, got " + quote_rest(line, first);
  if (t.empty() || t.size() % 4 != 0) throw ReadFailure(line.number, expected);
  for (std::size_t i = 0; i < t.size(); i += 4) {
    const auto lo = parse_number(t[i + 1]), hi = parse_number(t[i + 2]);
    if (t[i] != "(" || t[i + 3] != ")" || !lo || !hi || *lo > *hi)
      throw ReadFailure(line.number, expected);
    bone.limits.push_back({*lo, *hi});
  }
}

// One `key values` line of a block; `(` lines continue `limits`.
void read_block_line(const Line& line, const AsfDraft& draft, BlockDraft& block,
                     std::vector<FileNote>& notes) {
  if (line.starts_with('(')) {
    if (!block.in_limits)
      throw ReadFailure(line.number, "a '(lo hi)' line must follow 'limits' or another such line");
    read_limit_pairs(line, 0, block.bone);
    return;
  }
  const std::string key = lower(line.tokens[0]);
  block.in_limits = key == "limits";
  static const char* const kKeys[] = {"id", "name", "direction", "length", "axis", "dof", "limits"};
  bool known = false;
  for (const char* k : kKeys) known = known || key == k;
  if (!known) {
    notes.push_back({line.number, bone_label(block) + ": unknown key " +
                                      quote_token(line.tokens[0]) + " skipped"});
    return;
  }
  if (!block.key_lines.emplace(key, line.number).second) {
    throw ReadFailure(line.number,
                      bone_label(block) + ": " + key + " given twice; expected it once");
  }
  if (key == "id") read_id(line, draft);
  if (key == "name") read_name(line, draft, block.bone);
  if (key == "direction") read_direction(line, block.bone);
  if (key == "length") read_length(line, block.bone);
  if (key == "axis") read_axis(line, block.bone);
  if (key == "dof") read_dof(line, block.bone);
  if (key == "limits") read_limit_pairs(line, 1, block.bone);
}

// At `end`: every required key given, one limit per channel.
void check_block(const BlockDraft& block, int end_line) {
  for (const char* key : {"id", "name", "direction", "length", "axis"}) {
    if (block.key_lines.count(key) == 0) {
      throw ReadFailure(end_line,
                        bone_label(block) + " has no '" + key + "'; expected it before 'end'");
    }
  }
  const auto limits = block.key_lines.find("limits");
  if (limits == block.key_lines.end()) return;
  const std::size_t channels = block.bone.channels.size();
  if (channels == 0)
    throw ReadFailure(limits->second,
                      bone_label(block) + ": limits without dof; expected a dof line");
  if (block.bone.limits.size() != channels) {
    throw ReadFailure(limits->second, bone_label(block) + ": " +
                                          std::to_string(block.bone.limits.size()) +
                                          " limits for " + std::to_string(channels) +
                                          " dof channels; expected one (lo hi) pair per channel");
  }
}

void read_bone_block(AsfCursor& cursor, AsfDraft& draft, int begin_line) {
  BlockDraft block;
  for (;;) {
    if (cursor.at_section_end()) {
      throw ReadFailure(
          cursor.next_line_number(),
          "the bone block of line " + std::to_string(begin_line) + " has no 'end'; expected 'end'");
    }
    const Line& line = *cursor.peek();
    cursor.advance();
    if (lower(line.tokens[0]) == "end" && line.tokens.size() == 1) {
      check_block(block, line.number);
      draft.bones.push_back(std::move(block.bone));
      return;
    }
    read_block_line(line, draft, block, draft.notes);
  }
}

}  // namespace

void read_bonedata_section(AsfCursor& cursor, AsfDraft& draft) {
  while (!cursor.at_section_end()) {
    const Line& line = *cursor.peek();
    if (lower(line.tokens[0]) != "begin" || line.tokens.size() != 1) {
      throw ReadFailure(line.number,
                        ":bonedata: expected 'begin' of a bone block, got " + quote_rest(line, 0));
    }
    cursor.advance();
    read_bone_block(cursor, draft, line.number);
  }
}

}  // namespace jelly::skeleton::detail
