#include "build/symbols.hpp"

#include <sstream>

namespace jelly::grade {

bool DefinedSymbol::weak() const {
  return type == 'W' || type == 'V' || type == 'w' || type == 'v' || type == 'u';
}

std::map<std::string, std::vector<DefinedSymbol>> parse_nm(const std::string& output) {
  std::map<std::string, std::vector<DefinedSymbol>> out;
  std::istringstream in(output);
  std::string line;
  while (std::getline(in, line)) {
    const auto colon = line.find(": ");
    if (colon == std::string::npos) continue;
    std::string file = line.substr(0, colon);
    const auto bracket = file.find('[');
    if (bracket != std::string::npos && file.back() == ']') file = file.substr(0, bracket);
    std::istringstream rest(line.substr(colon + 2));
    DefinedSymbol s;
    std::string type;
    if (!(rest >> s.name >> type) || type.size() != 1) continue;
    s.type = type[0];
    out[file].push_back(s);
  }
  return out;
}

namespace {

bool starts(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// The C++ standard library's and the C++ ABI's own names, and the replaceable operators new and
// delete: a strong definition of one replaces the library's for the whole runner.
bool library_name(const std::string& n) {
  for (const char* p : {"_ZNSt", "_ZNKSt", "_ZSt", "_ZNVKSt", "_ZN9__gnu_cxx", "_ZNK9__gnu_cxx",
                        "_ZN10__cxxabiv1", "_ZNK10__cxxabiv1", "_Znw", "_Zna", "_Zdl", "_Zda",
                        "_ZTISt", "_ZTSSt", "_ZTVSt", "_ZTIN10__cxxabiv1", "_ZTVN10__cxxabiv1"})
    if (starts(n, p)) return true;
  return false;
}

}  // namespace

std::string refused_symbol(const std::string& file, const DefinedSymbol& symbol,
                           const std::set<std::string>& own,
                           const std::map<std::string, std::string>& others,
                           const FrameworkSymbols& framework) {
  const std::string& n = symbol.name;
  if (own.count(n)) return "";
  if (const auto it = others.find(n); it != others.end())
    return "is a task function of " + it->second + ", not of " + file + " (define it there)";
  if (framework.strong.count(n) || (framework.weak.count(n) && !symbol.weak()))
    return "is defined by the grader's own code (framework, runner or harness): a submission may "
           "not replace it";
  if (!starts(n, "_Z")) {
    if (symbol.weak() && starts(n, "DW.ref.")) return "";  // the exception personality's pointer
    return "is not a C++ function or variable name (extern \"C\" or assembler): it could replace "
           "a function of the C library or of the grader";
  }
  if (!symbol.weak() && library_name(n))
    return "is a function of the C++ standard library: a submission may not replace it";
  return "";  // the file's own helper (or an inline or template copy from the headers)
}

}  // namespace jelly::grade
