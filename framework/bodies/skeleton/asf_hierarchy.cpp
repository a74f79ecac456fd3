// The ASF's :hierarchy section and the tree it gives (kinematics contract §1, §11.7).
#include <string>

#include "asf_draft.hpp"

namespace jelly::skeleton::detail {

void read_hierarchy_section(AsfCursor& cursor, AsfDraft& draft) {
  const Line* begin = cursor.at_section_end() ? nullptr : cursor.peek();
  if (begin == nullptr || lower(begin->tokens[0]) != "begin" || begin->tokens.size() != 1) {
    const std::string got = begin == nullptr ? std::string("nothing") : quote_rest(*begin, 0);
    throw ReadFailure(cursor.next_line_number(), ":hierarchy: expected 'begin', got " + got);
  }
  cursor.advance();
  for (;;) {
    if (cursor.at_section_end()) {
      throw ReadFailure(cursor.next_line_number(),
                        ":hierarchy has no 'end'; expected 'end' after its lines");
    }
    const Line& line = *cursor.peek();
    cursor.advance();
    if (lower(line.tokens[0]) == "end" && line.tokens.size() == 1) {
      draft.has_hierarchy = true;
      draft.hierarchy_end_line = line.number;
      break;
    }
    if (line.tokens.size() < 2) {
      throw ReadFailure(line.number, ":hierarchy: " + quote_token(line.tokens[0]) +
                                         " has no children; expected 'parent child1 child2 …'");
    }
    HierarchyEntry entry{line.number, std::string(line.tokens[0]), {}};
    for (std::size_t i = 1; i < line.tokens.size(); ++i)
      entry.children.emplace_back(line.tokens[i]);
    draft.hierarchy.push_back(std::move(entry));
  }
  if (!cursor.at_section_end()) {
    throw ReadFailure(cursor.peek()->number, ":hierarchy: expected a section after 'end', got " +
                                                 quote_rest(*cursor.peek(), 0));
  }
}

namespace {

int bone_index(const std::vector<Bone>& bones, const std::string& name, int line) {
  for (std::size_t i = 0; i < bones.size(); ++i) {
    if (bones[i].name == name) return static_cast<int>(i);
  }
  throw ReadFailure(line, ":hierarchy: unknown bone " + quote_token(name) +
                              "; expected root or a bone of :bonedata");
}

// Every bone must lead up to the root; one that does not lies in or below a cycle.
void check_no_cycle(const std::vector<Bone>& bones, const std::vector<int>& parent_lines) {
  for (std::size_t i = 1; i < bones.size(); ++i) {
    int at = static_cast<int>(i);
    for (std::size_t steps = 0; at > 0 && steps <= bones.size(); ++steps) at = bones[at].parent;
    if (at != 0) {
      throw ReadFailure(parent_lines[i],
                        ":hierarchy: bone " + quote_token(bones[i].name) +
                            " does not lead up to root (a cycle); expected a tree under root");
    }
  }
}

}  // namespace

void resolve_hierarchy(std::vector<Bone>& bones, const AsfDraft& draft, int end_of_file) {
  std::vector<int> parent_lines(bones.size(), 0);
  for (const HierarchyEntry& entry : draft.hierarchy) {
    const int parent = bone_index(bones, entry.parent, entry.line);
    for (const std::string& name : entry.children) {
      const int child = bone_index(bones, name, entry.line);
      if (child == 0)
        throw ReadFailure(entry.line,
                          ":hierarchy: root cannot be a child; expected a bone of :bonedata");
      if (bones[child].parent >= 0) {
        throw ReadFailure(entry.line, ":hierarchy: bone " + quote_token(name) +
                                          " is already the child of " +
                                          quote_token(bones[bones[child].parent].name) + " (line " +
                                          std::to_string(parent_lines[child]) +
                                          "); expected one parent per bone");
      }
      bones[child].parent = parent;
      parent_lines[child] = entry.line;
      bones[parent].children.push_back(child);
    }
  }
  for (std::size_t i = 1; i < bones.size(); ++i) {
    if (bones[i].parent < 0) {
      const int line = draft.has_hierarchy ? draft.hierarchy_end_line : end_of_file;
      throw ReadFailure(line,
                        ":hierarchy: bone " + quote_token(bones[i].name) +
                            " is missing from it; expected every bone as the child of one bone");
    }
  }
  check_no_cycle(bones, parent_lines);
}

}  // namespace jelly::skeleton::detail
