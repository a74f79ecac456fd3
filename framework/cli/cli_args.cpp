#include "cli_args.hpp"

#include <algorithm>
#include <charconv>

namespace jelly::cli {

Args::Args(int argc, char** argv, int first, const std::vector<std::string>& value_flags,
           const std::vector<std::string>& switch_flags) {
  auto takes_value = [&](const std::string& f) {
    return std::find(value_flags.begin(), value_flags.end(), f) != value_flags.end();
  };
  auto is_switch = [&](const std::string& f) {
    return std::find(switch_flags.begin(), switch_flags.end(), f) != switch_flags.end();
  };
  for (int i = first; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg.size() < 2 || arg.compare(0, 2, "--") != 0 || arg == "--") {
      positionals_.push_back(arg);
      continue;
    }
    std::string flag = arg, inline_value;
    bool has_inline = false;
    if (const auto eq = arg.find('='); eq != std::string::npos) {
      flag = arg.substr(0, eq);
      inline_value = arg.substr(eq + 1);
      has_inline = true;
    }
    if (is_switch(flag) && !has_inline) {
      flags_[flag].emplace_back();
    } else if (takes_value(flag)) {
      if (has_inline) {
        flags_[flag].push_back(inline_value);
      } else if (i + 1 < argc) {
        flags_[flag].push_back(argv[++i]);
      } else {
        error_ = flag + " needs a value";
        return;
      }
    } else {
      error_ = "unknown option " + flag;
      return;
    }
  }
}

std::optional<std::string> Args::value(const std::string& flag) const {
  const auto it = flags_.find(flag);
  if (it == flags_.end() || it->second.empty()) return std::nullopt;
  return it->second.back();
}

std::vector<std::string> Args::values(const std::string& flag) const {
  const auto it = flags_.find(flag);
  return it == flags_.end() ? std::vector<std::string>{} : it->second;
}

bool Args::has(const std::string& flag) const { return flags_.count(flag) != 0; }

std::optional<long> parse_positive_integer(const std::string& text) {
  long v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || v <= 0) return std::nullopt;
  return v;
}

}  // namespace jelly::cli
