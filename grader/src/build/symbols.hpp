// Which external symbols a compiled task file may define (the link-time half of the sandbox): its
// own task functions, its helpers, and the inline/template copies every C++ file gets from the
// headers; never a symbol of the grader's framework, runner, harness or the C and C++ libraries,
// which would replace the grader's own code at link time (docs/grader.md, "Threat model").
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

namespace jelly::grade {

struct DefinedSymbol {
  std::string name;  ///< as in the object (mangled)
  char type = '?';   ///< nm's letter: T D B R C ... strong; W V w v u weak or unique
  bool weak() const;
};

/// Parses `nm -P -A -g --defined-only FILE...` output: file (for an archive "lib.a[member.o]",
/// reduced to "lib.a") → its defined external symbols.
std::map<std::string, std::vector<DefinedSymbol>> parse_nm(const std::string& output);

/// The defined external symbols of the framework's link inputs.
struct FrameworkSymbols {
  std::set<std::string> strong, weak;
};

/// Why the task file `file` may not define `symbol` ("" when it may). `own` are the task functions
/// of this file (what its stub defines), `others` the task functions of the other files (→ their
/// file).
std::string refused_symbol(const std::string& file, const DefinedSymbol& symbol,
                           const std::set<std::string>& own,
                           const std::map<std::string, std::string>& others,
                           const FrameworkSymbols& framework);

}  // namespace jelly::grade
