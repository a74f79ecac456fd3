// submission_metadata.yml of a Gradescope export (Ruby's Psych writes it), read with yaml-cpp.
// Only the instructor's grader reads class exports: a build without yaml-cpp (a student's
// self-check) has class_archives_none.cpp instead.
#include <yaml-cpp/yaml.h>
#include <set>
#include <stdexcept>

#include "inputs/submissions.hpp"

namespace jelly::grade {

namespace {

[[noreturn]] void yaml_error(const std::string& file, const YAML::Mark& at,
                             const std::string& what) {
  throw std::runtime_error(file + ":" + std::to_string(at.line + 1) + ": " + what);
}

/// Psych writes Ruby symbols as ":name": both spellings of a key are taken.
bool is_key(const YAML::Node& key, const char* name) {
  if (!key.IsScalar()) return false;
  const std::string& k = key.Scalar();
  return k == name || (k.size() > 1 && k[0] == ':' && k.compare(1, std::string::npos, name) == 0);
}

/// A submitter's scalar key (:name:, :sid:, :email:) as text; "" when absent or null.
std::string scalar_of(const YAML::Node& value, const std::string& file, const char* what) {
  if (!value || value.IsNull()) return "";
  if (!value.IsScalar())
    yaml_error(file, value.Mark(),
               std::string("expected a text for the submitter's :") + what + ":, found a " +
                   (value.IsSequence() ? "list" : "mapping"));
  return value.Scalar();
}

/// One item of a :submitters: list: a mapping of :name:, :sid:, :email: (other keys skipped).
GradescopeSubmitter read_submitter(const YAML::Node& item, const std::string& file) {
  if (!item.IsMap())
    yaml_error(file, item.Mark(),
               "expected a submitter (a mapping such as '- :name: ...'), found " +
                   (item.IsScalar() ? "'" + item.Scalar() + "'" : std::string("a list")));
  GradescopeSubmitter who;
  for (const auto& kv : item) {
    if (is_key(kv.first, "name")) who.name = scalar_of(kv.second, file, "name");
    if (is_key(kv.first, "sid")) who.sid = scalar_of(kv.second, file, "sid");
    if (is_key(kv.first, "email")) who.email = scalar_of(kv.second, file, "email");
  }
  return who;
}

/// One submission's mapping: its :submitters: list (every other key is skipped).
GradescopeEntry read_entry(const std::string& folder, const YAML::Node& key,
                           const YAML::Node& value, const std::string& file) {
  GradescopeEntry entry;
  entry.folder = folder;
  entry.line = key.Mark().line + 1;
  if (value.IsNull()) return entry;
  if (!value.IsMap())
    yaml_error(
        file, value.Mark(),
        "expected the submission's keys (:submitters:, ...) on the lines below " + folder + ":");
  for (const auto& kv : value) {
    if (!is_key(kv.first, "submitters") || kv.second.IsNull()) continue;
    if (!kv.second.IsSequence())
      yaml_error(file, kv.second.Mark(),
                 "expected the list of submitters on the lines below :submitters: of " + folder);
    for (const YAML::Node& item : kv.second) entry.submitters.push_back(read_submitter(item, file));
  }
  return entry;
}

}  // namespace

std::vector<GradescopeEntry> read_gradescope_metadata(const std::string& text,
                                                      const std::string& file) {
  std::vector<YAML::Node> documents;
  try {
    documents = YAML::LoadAll(text);
  } catch (const YAML::ParserException& e) {
    yaml_error(file, e.mark, e.msg + " (not YAML as Gradescope writes it)");
  }
  std::vector<GradescopeEntry> entries;
  std::set<std::string> seen;
  for (const YAML::Node& doc : documents) {
    if (doc.IsNull()) continue;
    if (!doc.IsMap())
      yaml_error(file, doc.Mark(),
                 "expected submission folder names followed by ':' (such as submission_123456:)");
    for (const auto& kv : doc) {
      if (!kv.first.IsScalar())
        yaml_error(file, kv.first.Mark(),
                   "expected a submission folder name followed by ':' (such as "
                   "submission_123456:)");
      const std::string folder = kv.first.Scalar();
      if (!seen.insert(folder).second)
        yaml_error(file, kv.first.Mark(), "the submission " + folder + " is listed twice");
      entries.push_back(read_entry(folder, kv.first, kv.second, file));
    }
  }
  return entries;
}

}  // namespace jelly::grade
