// The ASF reader's state while it reads a file (internal; asf_*.cpp).
#pragma once

#include <string>
#include <vector>

#include "jelly/skeleton/skeleton.hpp"
#include "jelly/skeleton/skeleton_files.hpp"
#include "skeleton_file_text.hpp"

namespace jelly::skeleton::detail {

/// Walks the lines of an ASF, skipping blank lines and comments (a first token starting with '#').
class AsfCursor {
 public:
  explicit AsfCursor(const std::vector<Line>& lines) : lines_(lines) {}
  /// The next line that is not blank or a comment, or nullptr at the end of the file.
  const Line* peek();
  /// Consumes the line peek() returned.
  void advance() { ++at_; }
  /// Whether the next line starts a section (':') or the file ends.
  bool at_section_end() {
    const Line* l = peek();
    return l == nullptr || l->starts_with(':');
  }
  /// The line of the next section, or the end of the file's line.
  int next_line_number() {
    const Line* l = peek();
    return l != nullptr ? l->number : end_of_file_line(lines_);
  }

 private:
  const std::vector<Line>& lines_;
  std::size_t at_ = 0;
};

/// One `parent child1 child2 …` line of :hierarchy.
struct HierarchyEntry {
  int line = 0;
  std::string parent;
  std::vector<std::string> children;
};

struct AsfDraft {
  Bone root;  ///< valid when has_root
  bool has_root = false;
  std::vector<Bone> bones;  ///< the non-root bones in file order (ids 1, 2, …)
  bool has_hierarchy = false;
  int hierarchy_end_line = 0;
  std::vector<HierarchyEntry> hierarchy;
  std::vector<FileNote> notes;
};

/// The body of :root (`order`, `axis`, `position`, `orientation`); `section_line` is the :root
/// line.
void read_root_section(AsfCursor& cursor, AsfDraft& draft, int section_line);
/// The `begin … end` blocks of :bonedata.
void read_bonedata_section(AsfCursor& cursor, AsfDraft& draft);
/// The `begin … end` of :hierarchy, its lines kept by name until the whole file is read.
void read_hierarchy_section(AsfCursor& cursor, AsfDraft& draft);
/// Sets every bone's parent and children from the hierarchy; `end_of_file` for errors with no line.
void resolve_hierarchy(std::vector<Bone>& bones, const AsfDraft& draft, int end_of_file);

}  // namespace jelly::skeleton::detail
