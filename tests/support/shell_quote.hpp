// Command lines for popen in the tests: paths of the source and build folders quoted for the shell.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

namespace jelly::testing {

/// WORD in single quotes, one word for the shell whatever it holds.
inline std::string shell_quoted(const std::string& word) {
  std::string q = "'";
  for (char c : word) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// ARGUMENTS with every occurrence of the source or build folder quoted for the shell: a clone may
/// live in a folder whose path has a space in it ("/tmp/jelly lab/wt"), and the tests build their
/// paths from these folders. `'/tmp/jelly lab/wt'/scenes/x.toml` is one shell word.
inline std::string quote_tree_paths(const std::string& arguments) {
  std::vector<std::string> roots = {JELLY_SOURCE_DIR, JELLY_BINARY_DIR};
  std::sort(roots.begin(), roots.end(),
            [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
  std::string out;
  for (std::size_t i = 0; i < arguments.size();) {
    bool matched = false;
    for (const std::string& root : roots)
      if (!root.empty() && arguments.compare(i, root.size(), root) == 0) {
        out += shell_quoted(root);
        i += root.size();
        matched = true;
        break;
      }
    if (!matched) out += arguments[i++];
  }
  return out;
}

}  // namespace jelly::testing
