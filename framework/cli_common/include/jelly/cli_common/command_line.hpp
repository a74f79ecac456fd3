// The command line of every Jelly Lab program (jelly and its subcommands, jelly-lab, jelly-grade),
// read by CLI11 and reported one way: `PROGRAM: what was wrong` naming the option and what it
// expects, then a usage text or a pointer to --help, exit code kExitUsage; -h/--help prints the
// program's hand-written help on stdout (kExitOk). Options are declared on the Command itself
// (it is a CLI::App), bound to typed variables and checked by the validators below.
#pragma once

#include <CLI/CLI.hpp>

#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "jelly/cli_common/exit_codes.hpp"

namespace jelly::cli {

/// One command's parser. An option given twice keeps its last value (repeated() collects them
/// all); an unknown option or a stray argument is an error; no short forms but -h.
class Command : public CLI::App {
 public:
  /// `program` starts every error line ("jelly run"); `help` is printed for -h/--help;
  /// `after_error` follows an error line (a usage text, or "(see jelly run --help)\n").
  Command(std::string program, std::string help, std::string after_error)
      : CLI::App("", program),
        program_(std::move(program)),
        help_(std::move(help)),
        after_error_(std::move(after_error)) {
    set_help_flag("-h,--help");
    // CLI11's default on Windows reads "/x" as the option x: a path such as /home/a/scene.toml
    // (MinGW under wine, MSYS) would be an unknown option. Options are --long only, everywhere.
    allow_windows_style_options(false);
    option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    allow_extras();  // reported by parse_args() as "unknown option --x" / "unexpected argument 'x'"
  }

  /// An option taking one value per occurrence, every occurrence kept in order (--set K=V ...).
  CLI::Option* repeated(const std::string& name, std::vector<std::string>& into,
                        const std::string& value_name) {
    return add_option(name, into)
        ->type_name(value_name)
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  }

  /// Parses argv[first], ..., argv[argc - 1]. nullopt: parsed, carry on. Otherwise the exit code
  /// to return at once: kExitOk after printing the help, kExitUsage after printing the error.
  std::optional<int> parse_args(int argc, char** argv, int first) {
    std::vector<std::string> args;  // CLI11 takes them last first
    for (int i = argc - 1; i >= first; --i) args.emplace_back(argv[i]);
    try {
      parse(args);
    } catch (const CLI::CallForHelp&) {
      std::fputs(help_.c_str(), stdout);
      return kExitOk;
    } catch (const CLI::ArgumentMismatch& e) {
      return error(missing_value(e.what()));
    } catch (const CLI::ParseError& e) {
      return error(e.what());
    }
    if (!remaining().empty()) {
      const std::string extra = remaining().front();
      if (extra.size() > 1 && extra[0] == '-')
        return error("unknown option " + extra.substr(0, extra.find('=')));
      return error("unexpected argument '" + extra + "'");
    }
    return std::nullopt;
  }

  /// Reports a command-line error found after parsing (a combination of options that does not
  /// apply) exactly as parse_args() reports its own; returns kExitUsage.
  int error(const std::string& message) const {
    std::fprintf(stderr, "%s: %s\n%s", program_.c_str(), message.c_str(), after_error_.c_str());
    return kExitUsage;
  }

 private:
  /// CLI11's "--dt: 1 required H missing" as "--dt needs a value (H)"; other texts unchanged.
  static std::string missing_value(const std::string& what) {
    const auto colon = what.find(": 1 required ");
    const std::string tail = " missing";
    if (colon == std::string::npos || what.size() < tail.size() ||
        what.compare(what.size() - tail.size(), tail.size(), tail) != 0)
      return what;
    const std::size_t from = colon + 13;
    return what.substr(0, colon) + " needs a value (" +
           what.substr(from, what.size() - tail.size() - from) + ")";
  }

  std::string program_, help_, after_error_;
};

// ---- validators: the error reads "OPTION: expected ..., got 'TEXT'" ----

namespace detail {
inline std::optional<long> whole(const std::string& text) {
  long v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size()) return std::nullopt;
  return v;
}
inline std::optional<double> number(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}
}  // namespace detail

/// A whole number from `lo` to `hi` (no upper bound when hi is LONG_MAX).
inline CLI::Validator whole_number(long lo, long hi = LONG_MAX) {
  const std::string range = hi == LONG_MAX
                                ? "≥ " + std::to_string(lo)
                                : "from " + std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& text) {
        const auto v = detail::whole(text);
        return v && *v >= lo && *v <= hi
                   ? std::string()
                   : "expected a whole number " + range + ", got '" + text + "'";
      },
      "");
}

/// A finite number > 0 (or ≥ 0 with `zero_ok`).
inline CLI::Validator positive_number(bool zero_ok = false) {
  return CLI::Validator(
      [zero_ok](std::string& text) {
        const auto v = detail::number(text);
        return v && (zero_ok ? *v >= 0.0 : *v > 0.0)
                   ? std::string()
                   : std::string("expected a number ") + (zero_ok ? "≥ 0" : "> 0") + ", got '" +
                         text + "'";
      },
      "");
}

/// A finite number ≥ `lo`.
inline CLI::Validator number_at_least(double lo) {
  return CLI::Validator(
      [lo](std::string& text) {
        const auto v = detail::number(text);
        char bound[32];
        std::snprintf(bound, sizeof bound, "%g", lo);
        return v && *v >= lo ? std::string()
                             : std::string("expected a number ≥ ") + bound + ", got '" + text + "'";
      },
      "");
}

/// One of `choices`, spelled exactly.
inline CLI::Validator one_of(std::vector<std::string> choices) {
  std::string list;
  for (const std::string& c : choices) list += (list.empty() ? "" : ", ") + c;
  return CLI::Validator(
      [choices, list](std::string& text) {
        for (const std::string& c : choices)
          if (c == text) return std::string();
        return "expected one of " + list + ", got '" + text + "'";
      },
      "");
}

}  // namespace jelly::cli
