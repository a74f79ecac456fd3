#include "class/similarity.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "class/csv.hpp"
#include "inputs/files.hpp"
#include "reports/html_page.hpp"
#include "reports/text_safety.hpp"
#include "sandbox/process.hpp"

namespace jelly::grade {

namespace {

constexpr std::size_t kMaxFileBytes = 1ULL << 20;  // as the build's source_bytes: larger is refused
constexpr int kMaxShownLines = 60;                 // per side of one region in the HTML page
constexpr std::size_t kMaxShownPairs = 200;        // pairs shown in full (all are in the table)

// The file the build grades as task file `name` (build.cpp: find_named, find_lms_named): the
// shallowest one called `name`; else the shallowest LMS bulk-download name for it, the latest
// resubmission first. Empty when there is none.
fs::path find_task_file(const fs::path& root, const std::string& name) {
  const std::vector<fs::path> exact = find_named(root, name);
  return exact.empty() ? find_lms_named(root, name) : exact.front();
}

// The bytes of a submitted file, or "" with `why` set: a symbolic link, a hard link (a second name
// of some other file), anything but a regular file, or a file above kMaxFileBytes is not read.
std::string read_task_file(const fs::path& p, std::string& why) {
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(p, ec);
  if (ec || fs::is_symlink(st)) {
    why = ec ? "cannot be read" : "is a symbolic link";
    return "";
  }
  if (!fs::is_regular_file(st)) {
    why = "is not a regular file";
    return "";
  }
  if (fs::hard_link_count(p, ec) > 1) {
    why = "is a hard link";
    return "";
  }
  if (fs::file_size(p, ec) > kMaxFileBytes) {
    why = "is larger than " + std::to_string(kMaxFileBytes >> 10) + " KiB";
    return "";
  }
  std::string text = read_file(p);
  if (text.size() > kMaxFileBytes) {
    why = "is larger than " + std::to_string(kMaxFileBytes >> 10) + " KiB";
    return "";
  }
  return text;
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::string line;
  std::istringstream in(text);
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

// A line without its white space: how a line is compared with the stub's lines.
std::string squeeze(const std::string& line) {
  std::string s;
  for (const char c : line)
    if (c != ' ' && c != '\t' && c != '\r' && c != '\v' && c != '\f') s += c;
  return s;
}

// For each line: does it hold code (something besides white space, comments and a preprocessor
// directive, which sim_c++ ignores too)? A small C++ scanner: comments, string and character
// literals (raw strings included), so that "//" in a string is not a comment.
std::vector<char> code_lines(const std::vector<std::string>& lines) {
  std::vector<char> code(lines.size(), 0);
  enum { Normal, Block, Str, Chr, Raw } state = Normal;
  std::string raw_end;  // )delim" of the raw string being read
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const std::string& l = lines[n];
    bool directive = false, seen = false;
    for (std::size_t i = 0; i < l.size(); ++i) {
      const char c = l[i];
      const char next = i + 1 < l.size() ? l[i + 1] : '\0';
      switch (state) {
        case Normal:
          if (c == ' ' || c == '\t' || c == '\v' || c == '\f') break;
          if (c == '/' && next == '/') {
            i = l.size();
            break;
          }
          if (c == '/' && next == '*') {
            state = Block;
            ++i;
            break;
          }
          if (!seen && c == '#') directive = true;
          seen = true;
          code[n] = 1;
          if (c == 'R' && next == '"' &&
              (i == 0 ||
               !(std::isalnum(static_cast<unsigned char>(l[i - 1])) || l[i - 1] == '_'))) {
            const std::size_t open = l.find('(', i + 2);
            if (open != std::string::npos && open - (i + 2) <= 16) {
              raw_end = ")" + l.substr(i + 2, open - (i + 2)) + "\"";
              state = Raw;
              i = open;
            }
          } else if (c == '"') {
            state = Str;
          } else if (c == '\'' && !(i > 0 && std::isxdigit(static_cast<unsigned char>(l[i - 1])))) {
            state = Chr;  // (not a digit separator: 1'000)
          }
          break;
        case Block:
          if (c == '*' && next == '/') {
            state = Normal;
            ++i;
          }
          break;
        case Str:
        case Chr:
          code[n] = 1;
          if (c == '\\')
            ++i;
          else if (c == (state == Str ? '"' : '\''))
            state = Normal;
          break;
        case Raw:
          code[n] = 1;
          if (l.compare(i, raw_end.size(), raw_end) == 0) {
            i += raw_end.size() - 1;
            state = Normal;
          }
          break;
      }
    }
    if (state == Str || state == Chr) state = Normal;  // an unterminated literal ends at the line
    if (directive) code[n] = 0;
  }
  return code;
}

// The C++ code blocks (```cpp, ```c++, ```cc, ```cxx, ```c) of the assignment's handout pages
// (the folder of the manifest's `handout`): given code, as the stubs are.
std::vector<std::string> handout_code(const GradeConfig& config) {
  std::vector<std::string> blocks;
  const std::string& front = config.assignment().manifest.handout;
  if (front.empty()) return blocks;
  std::vector<fs::path> pages;
  std::error_code ec;
  for (fs::recursive_directory_iterator it((config.assignments_dir() / front).parent_path(), ec),
       end;
       !ec && it != end; it.increment(ec))
    if (it->path().extension() == ".md" && it->is_regular_file(ec)) pages.push_back(it->path());
  std::sort(pages.begin(), pages.end());
  for (const fs::path& page : pages) {
    std::string block;
    bool in = false, cxx = false;
    for (const std::string& l : split_lines(read_file(page))) {
      const std::size_t start = l.find_first_not_of(' ');
      if (start != std::string::npos && l.compare(start, 3, "```") == 0) {
        if (in && cxx && !block.empty()) blocks.push_back(block);
        if (!in) {
          std::string info = l.substr(start + 3);
          info = info.substr(0, info.find_first_of(" {"));
          cxx = info == "cpp" || info == "c++" || info == "cc" || info == "cxx" || info == "c";
        }
        in = !in;
        block.clear();
      } else if (in) {
        block += l + "\n";
      }
    }
  }
  return blocks;
}

// One submission's copy of one task file.
struct TaskCopy {
  bool present = false;
  std::string shown;               // its path in the submission (student-controlled)
  std::string why;                 // why it was not compared (missing, refused)
  std::vector<std::string> lines;  // as submitted
  std::vector<char> stub;  // given code: identical to a line of the stub or of the handout's code,
                           // or in a run with either
  std::vector<char> code;  // the line holds code
  bool counts(std::size_t line) const {  // 1-based
    return line >= 1 && line <= lines.size() && code[line - 1] && !stub[line - 1];
  }
};

// One region two submissions share: lines [a1, a2] of a's copy of task file `task` and [b1, b2] of
// b's, `tokens` tokens long.
struct Run {
  std::size_t a = 0, b = 0, task = 0;
  long a1 = 0, a2 = 0, b1 = 0, b2 = 0, tokens = 0;
};

// "NAME: line A-B" (one side of a sim_c++ -n line, trailing blanks allowed). False when it is not.
bool parse_side(const std::string& s, std::string& name, long& from, long& to) {
  const std::size_t colon = s.find(": line ");
  if (colon == std::string::npos || colon == 0) return false;
  name = s.substr(0, colon);
  const char* p = s.c_str() + colon + 7;
  char* end = nullptr;
  from = std::strtol(p, &end, 10);
  if (end == p || *end != '-') return false;
  p = end + 1;
  to = std::strtol(p, &end, 10);
  if (end == p) return false;
  for (; *end; ++end)
    if (*end != ' ') return false;
  return from >= 1 && to >= from;
}

// sim_c++'s -n output: "A.cpp: line 4-59      |B.cpp: line 4-59      [577]". Every file name in it
// is one the grader chose ("<index>.cpp", "stub.cpp"), so no submitted text can take part in it.
struct SimLine {
  std::string left, right;
  long l1 = 0, l2 = 0, r1 = 0, r2 = 0, tokens = 0;
};
bool parse_sim_line(const std::string& line, SimLine& out) {
  const std::size_t bar = line.find('|');
  const std::size_t open = line.rfind('[');
  if (bar == std::string::npos || open == std::string::npos || open < bar) return false;
  const std::size_t close = line.find(']', open);
  if (close == std::string::npos) return false;
  if (!parse_side(line.substr(0, bar), out.left, out.l1, out.l2)) return false;
  if (!parse_side(line.substr(bar + 1, open - bar - 1), out.right, out.r1, out.r2)) return false;
  out.tokens = std::strtol(line.c_str() + open + 1, nullptr, 10);
  return out.tokens > 0;
}

std::string percent(double p) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(0);
  s << p;
  return s.str();
}

std::string shown(const std::string& student_text) { return safe_excerpt(student_text, 200); }

// Lines [from, to] of a copy as an HTML <pre>: line numbers, escaped text, stub lines dimmed.
std::string html_lines(const TaskCopy& f, long from, long to) {
  std::ostringstream o;
  o << "<pre>";
  long shown_lines = 0;
  for (long n = from; n <= to && n <= static_cast<long>(f.lines.size()); ++n) {
    if (shown_lines++ == kMaxShownLines) {
      o << "<i>… " << (to - n + 1) << " more lines</i>\n";
      break;
    }
    const bool stub = f.stub[static_cast<std::size_t>(n - 1)];
    o << (stub ? "<span class=\"stub\">" : "") << "<span class=\"n\">" << n << "</span> "
      << html_escape(safe_excerpt(f.lines[static_cast<std::size_t>(n - 1)], 240))
      << (stub ? "</span>" : "") << "\n";
  }
  o << "</pre>";
  return o.str();
}

struct Pair {
  std::size_t a = 0, b = 0;
  double pa = 0.0, pb = 0.0;  // percent of a's (b's) counted lines in shared regions
  long la = 0, lb = 0;        // those lines
  std::vector<Run> runs;
  double top() const { return std::max(pa, pb); }
};

// Why a submission's task file was not compared (student id: file: why), for the report.
std::vector<std::string> notes_for(const std::vector<SimilarityInput>& inputs,
                                   const std::vector<std::string>& tasks,
                                   const std::vector<std::vector<TaskCopy>>& copies) {
  std::vector<std::string> notes;
  for (std::size_t i = 0; i < inputs.size(); ++i)
    for (std::size_t t = 0; t < tasks.size(); ++t)
      if (!copies[i][t].present)
        notes.push_back(shown(inputs[i].id) + ": " + tasks[t] +
                        (copies[i][t].shown.empty() ? "" : " (" + shown(copies[i][t].shown) + ")") +
                        " " + copies[i][t].why);
  return notes;
}

constexpr const char* kEvidence =
    "This is evidence for a person to read, never a verdict. A high percentage says only that two "
    "submissions share long regions of the same token sequence (identifiers, numbers, strings, "
    "layout and comments are ignored). A short task with one natural solution, code both took "
    "from a lecture or a book, and permitted work in pairs produce such regions too. Read the "
    "regions side by side, and hear the students, before deciding anything.";

// The pairs, flagged (at or above the threshold, highest first, their regions in file order) and
// the ten highest below it, with each submission's own code lines.
struct Ranking {
  std::vector<long> own;
  std::vector<Pair> flagged, below;
};

Ranking rank_pairs(const std::vector<SimilarityInput>& inputs,
                   const std::vector<std::vector<TaskCopy>>& copies, const std::vector<Run>& runs,
                   const SimilarityOptions& options) {
  Ranking ranking;
  std::vector<long>& own = ranking.own;
  std::vector<Pair>& flagged = ranking.flagged;
  std::vector<Pair>& below = ranking.below;
  // Each submission's own code lines: lines with code that are not stub lines.
  own.assign(inputs.size(), 0);
  for (std::size_t i = 0; i < inputs.size(); ++i)
    for (const TaskCopy& c : copies[i])
      if (c.present)
        for (std::size_t n = 1; n <= c.lines.size(); ++n) own[i] += c.counts(n);
  std::map<std::pair<std::size_t, std::size_t>, Pair> by_pair;
  for (const Run& r : runs) {
    Pair& p = by_pair[{r.a, r.b}];
    p.a = r.a;
    p.b = r.b;
    p.runs.push_back(r);
  }
  for (auto& [key, p] : by_pair) {
    std::set<std::pair<std::size_t, long>> in_a, in_b;
    for (const Run& r : p.runs) {
      for (long n = r.a1; n <= r.a2; ++n)
        if (copies[p.a][r.task].counts(static_cast<std::size_t>(n))) in_a.insert({r.task, n});
      for (long n = r.b1; n <= r.b2; ++n)
        if (copies[p.b][r.task].counts(static_cast<std::size_t>(n))) in_b.insert({r.task, n});
    }
    p.la = static_cast<long>(in_a.size());
    p.lb = static_cast<long>(in_b.size());
    p.pa = own[p.a] ? 100.0 * static_cast<double>(p.la) / static_cast<double>(own[p.a]) : 0.0;
    p.pb = own[p.b] ? 100.0 * static_cast<double>(p.lb) / static_cast<double>(own[p.b]) : 0.0;
    if ((p.la > 0 || p.lb > 0) && p.top() >= options.threshold)
      flagged.push_back(std::move(p));
    else
      below.push_back(std::move(p));
  }
  const auto order = [&](const Pair& x, const Pair& y) {
    if (x.top() != y.top()) return x.top() > y.top();
    if (std::min(x.pa, x.pb) != std::min(y.pa, y.pb))
      return std::min(x.pa, x.pb) > std::min(y.pa, y.pb);
    return std::tie(inputs[x.a].id, inputs[x.b].id) < std::tie(inputs[y.a].id, inputs[y.b].id);
  };
  std::sort(flagged.begin(), flagged.end(), order);
  std::sort(below.begin(), below.end(), order);
  if (below.size() > 10) below.resize(10);
  for (Pair& p : flagged)
    std::sort(p.runs.begin(), p.runs.end(), [](const Run& x, const Run& y) {
      return std::tie(x.task, x.a1, x.b1) < std::tie(y.task, y.a1, y.b1);
    });
  return ranking;
}

// similarity.json: every flagged pair with its regions, the highest below the threshold.
nlohmann::json similarity_json(const GradeConfig& config,
                               const std::vector<SimilarityInput>& inputs,
                               const std::vector<std::vector<TaskCopy>>& copies,
                               const Ranking& ranking, const std::vector<std::string>& notes,
                               std::size_t compared, const SimilarityOptions& options) {
  const std::vector<std::string>& tasks = config.task_files();
  const std::vector<long>& own = ranking.own;
  const std::vector<Pair>& flagged = ranking.flagged;
  const std::vector<Pair>& below = ranking.below;
  nlohmann::json j;
  j["assignment"] = config.assignment().id;
  j["evidence_not_verdict"] = kEvidence;
  j["threshold_percent"] = options.threshold;
  j["min_run_tokens"] = options.min_run;
  j["submissions"] = inputs.size();
  j["pairs_compared"] = compared;
  j["pairs_flagged"] = flagged.size();
  j["pairs"] = nlohmann::json::array();
  for (const Pair& p : flagged) {
    nlohmann::json jp;
    jp["a"] = shown(inputs[p.a].id);
    jp["b"] = shown(inputs[p.b].id);
    jp["percent_a"] = std::round(p.pa * 10.0) / 10.0;
    jp["percent_b"] = std::round(p.pb * 10.0) / 10.0;
    jp["shared_lines_a"] = p.la;
    jp["shared_lines_b"] = p.lb;
    jp["own_lines_a"] = own[p.a];
    jp["own_lines_b"] = own[p.b];
    jp["regions"] = nlohmann::json::array();
    for (const Run& r : p.runs)
      jp["regions"].push_back({{"task_file", tasks[r.task]},
                               {"a_file", shown(copies[p.a][r.task].shown)},
                               {"a_lines", {r.a1, r.a2}},
                               {"b_file", shown(copies[p.b][r.task].shown)},
                               {"b_lines", {r.b1, r.b2}},
                               {"tokens", r.tokens}});
    j["pairs"].push_back(jp);
  }
  // How close the rest came: the threshold is a choice, and this shows what it left out.
  j["highest_below_threshold"] = nlohmann::json::array();
  for (const Pair& p : below)
    j["highest_below_threshold"].push_back({{"a", shown(inputs[p.a].id)},
                                            {"b", shown(inputs[p.b].id)},
                                            {"percent_a", std::round(p.pa * 10.0) / 10.0},
                                            {"percent_b", std::round(p.pb * 10.0) / 10.0}});
  j["not_compared"] = notes;

  return j;
}

// similarity.html (grader/templates/similarity.html.mustache): the table of flagged pairs and the
// regions of the first kMaxShownPairs side by side.
std::string similarity_html(const GradeConfig& config, const std::vector<SimilarityInput>& inputs,
                            const std::vector<std::vector<TaskCopy>>& copies,
                            const std::vector<Pair>& flagged, const std::vector<std::string>& notes,
                            std::size_t compared, const std::string& settings,
                            const SimilarityOptions& options) {
  std::ostringstream threshold;
  threshold << options.threshold;
  HtmlData page;
  page.set("assignment", config.assignment().id);
  page.set("evidence", kEvidence);
  page.set("submissions", std::to_string(inputs.size()));
  page.set("compared", std::to_string(compared));
  page.set("flagged", std::to_string(flagged.size()));
  page.set("threshold", threshold.str());
  page.set("min_run", std::to_string(options.min_run));
  page.set("settings", settings);
  page.set("has_pairs", !flagged.empty());
  HtmlList pairs, shown_pairs;
  for (std::size_t k = 0; k < flagged.size(); ++k) {
    const Pair& p = flagged[k];
    HtmlData row;
    row.set("number", std::to_string(k + 1));
    row.set("shown", k < kMaxShownPairs);
    row.set("a", shown(inputs[p.a].id));
    row.set("b", shown(inputs[p.b].id));
    row.set("percent_a", percent(p.pa));
    row.set("percent_b", percent(p.pb));
    row.set("lines_a", std::to_string(p.la));
    row.set("lines_b", std::to_string(p.lb));
    pairs.push_back(row);
    if (k >= kMaxShownPairs) continue;
    HtmlList regions;
    for (const Run& r : p.runs) {
      const TaskCopy& fa = copies[p.a][r.task];
      const TaskCopy& fb = copies[p.b][r.task];
      regions.push_back(HtmlObject{{"file_a", shown(fa.shown)},
                                   {"file_b", shown(fb.shown)},
                                   {"a1", std::to_string(r.a1)},
                                   {"a2", std::to_string(r.a2)},
                                   {"b1", std::to_string(r.b1)},
                                   {"b2", std::to_string(r.b2)},
                                   {"tokens", std::to_string(r.tokens)},
                                   {"lines_a", html_lines(fa, r.a1, r.a2)},
                                   {"lines_b", html_lines(fb, r.b1, r.b2)}});
    }
    row.set("regions", regions);
    shown_pairs.push_back(row);
  }
  page.set("pairs", pairs);
  page.set("shown_pairs", shown_pairs);
  page.set("more_pairs", flagged.size() > kMaxShownPairs);
  page.set("max_shown", std::to_string(kMaxShownPairs));
  page.set("has_notes", !notes.empty());
  HtmlList note_list;
  for (const std::string& n : notes) note_list.push_back(n);
  page.set("notes", note_list);
  return render_html(similarity_html_template(), "similarity.html.mustache", page);
}

int report(const GradeConfig& config, const std::vector<SimilarityInput>& inputs,
           const std::vector<std::vector<TaskCopy>>& copies, const std::vector<Run>& runs,
           const std::vector<std::string>& notes, std::size_t handout_blocks, const fs::path& out,
           const SimilarityOptions& options) {
  const Ranking ranking = rank_pairs(inputs, copies, runs, options);
  const std::size_t compared = inputs.size() * (inputs.size() - (inputs.empty() ? 0 : 1)) / 2;
  const std::string settings =
      "sim_c++ -e -r" + std::to_string(options.min_run) +
      " on each task file over the whole class, the stub and the handout's "
      "C++ code blocks (" +
      std::to_string(handout_blocks) + ") as old files";
  const nlohmann::json j =
      similarity_json(config, inputs, copies, ranking, notes, compared, options);
  write_file_atomically(out / "similarity.json", j.dump(1) + "\n");
  write_file_atomically(
      out / "similarity.html",
      similarity_html(config, inputs, copies, ranking.flagged, notes, compared, settings, options));
  return static_cast<int>(ranking.flagged.size());
}

// The squeezed lines the class was given for one task file: the stub's and the handout code's.
std::set<std::string> given_lines(const std::string& stub_text,
                                  const std::vector<std::string>& handout) {
  std::set<std::string> stub_lines;
  for (const std::string& l : split_lines(stub_text))
    if (const std::string s = squeeze(l); !s.empty()) stub_lines.insert(s);
  for (const std::string& block : handout)
    for (const std::string& l : split_lines(block))
      if (const std::string s = squeeze(l); !s.empty()) stub_lines.insert(s);
  return stub_lines;
}

// Marks the copy's lines that are given (`stub_lines`) and returns the text sim_c++ reads: the
// copy with its given lines blanked.
std::string text_for_sim(TaskCopy& c, const std::set<std::string>& stub_lines) {
  c.stub.assign(c.lines.size(), 0);
  std::string for_sim;
  for (std::size_t n = 0; n < c.lines.size(); ++n) {
    const std::string s = squeeze(c.lines[n]);
    c.stub[n] = !s.empty() && stub_lines.count(s);
    // Controls (NUL among them) become blanks: sim_c++ and this file keep the same lines.
    if (!c.stub[n])
      for (const char ch : c.lines[n])
        for_sim += static_cast<unsigned char>(ch) < 0x20 && ch != '\t' ? ' ' : ch;
    for_sim += '\n';
  }
  return for_sim;
}

// Anything but stub lines?
bool has_own_code(const TaskCopy& c) {
  bool own = false;
  for (std::size_t n = 0; n < c.lines.size(); ++n) own = own || (c.code[n] && !c.stub[n]);
  return own;
}

// Why sim_c++ did not end well, for the error message.
std::string sim_failure(const ChildResult& r, const SimilarityOptions& options) {
  return !r.started    ? "did not start: " + r.start_error
         : r.timed_out ? "took longer than " + percent(options.timeout_s) + " s"
         : r.signal    ? "was ended by " + describe_signal(r.signal)
                       : "failed with exit status " + std::to_string(r.exit_code);
}

// One sim_c++ run per task file over the whole class, in `work`: every submission's copy of every
// task file, its stub lines blanked in the copy sim_c++ reads, and the runs two copies share.
class ClassComparison {
 public:
  ClassComparison(const GradeConfig& config, const std::vector<SimilarityInput>& inputs,
                  const fs::path& sim, const fs::path& work, const SimilarityOptions& options)
      : config_(config),
        inputs_(inputs),
        options_(options),
        sim_(sim),
        work_(work),
        tasks_(config.task_files()),
        copies_(inputs.size(), std::vector<TaskCopy>(tasks_.size())),
        handout_(handout_code(config)) {}

  void compare_all() {
    for (std::size_t t = 0; t < tasks_.size(); ++t) compare_task(t);
  }

  int write_report(const fs::path& out) const {
    return report(config_, inputs_, copies_, runs_, notes_for(inputs_, tasks_, copies_),
                  handout_.size(), out, options_);
  }

 private:
  void compare_task(std::size_t t) {
    const std::string stub_text = read_file(config_.assignments_dir() / tasks_[t]);
    if (stub_text.empty())
      throw std::runtime_error("similarity: cannot read the stub " +
                               (config_.assignments_dir() / tasks_[t]).string());
    const std::set<std::string> stub_lines = given_lines(stub_text, handout_);
    const fs::path dir = work_ / std::to_string(t);
    write_given_files(dir, stub_text);
    std::size_t present = 0;
    for (std::size_t i = 0; i < inputs_.size(); ++i)
      present += prepare_copy(i, t, stub_lines, dir) ? 1 : 0;
    if (present < 2) return;
    run_sim(t, dir);
    read_runs(t, dir);
  }

  // The given code, as sim_c++'s old files.
  void write_given_files(const fs::path& dir, const std::string& stub_text) const {
    fs::create_directories(dir);
    write_file_atomically(dir / "stub.cpp", stub_text);
    for (std::size_t h = 0; h < handout_.size(); ++h)
      write_file_atomically(dir / ("handout" + std::to_string(h) + ".cpp"), handout_[h]);
  }

  // Reads submission i's copy of task file t and, when it holds code of its own, writes the text
  // sim_c++ reads as dir/<i>.cpp. True when it is compared.
  bool prepare_copy(std::size_t i, std::size_t t, const std::set<std::string>& stub_lines,
                    const fs::path& dir) {
    TaskCopy& c = copies_[i][t];
    const fs::path file = find_task_file(inputs_[i].folder, tasks_[t]);
    if (file.empty()) {
      c.why = "not found";
      return false;
    }
    // Lexically: fs::relative would follow a symbolic link and show where it points.
    const fs::path rel = file.lexically_relative(inputs_[i].folder);
    c.shown = (rel.empty() ? file.filename() : rel).generic_string();
    const std::string text = read_task_file(file, c.why);
    if (!c.why.empty()) return false;
    c.lines = split_lines(text);
    c.code = code_lines(c.lines);
    const std::string for_sim = text_for_sim(c, stub_lines);
    if (!has_own_code(c)) {
      c.why = "holds only given lines (the stub's, the handout's code)";
      return false;
    }
    c.present = true;
    std::ofstream(dir / (std::to_string(i) + ".cpp"), std::ios::binary) << for_sim;
    return true;
  }

  std::vector<std::string> sim_argv(std::size_t t) const {
    std::vector<std::string> argv = {
        sim_.string(), "-e",     "-n", "-s", "-T", "-r" + std::to_string(options_.min_run),
        "-o",          "sim.out"};
    for (std::size_t i = 0; i < inputs_.size(); ++i)
      if (copies_[i][t].present) argv.push_back(std::to_string(i) + ".cpp");
    argv.push_back("/");  // the given code are "old" files: runs against them mark it
    argv.push_back("stub.cpp");
    for (std::size_t h = 0; h < handout_.size(); ++h)
      argv.push_back("handout" + std::to_string(h) + ".cpp");
    return argv;
  }

  void run_sim(std::size_t t, const fs::path& dir) const {
    Limits lim = trusted_tool_limits(options_.timeout_s);
    lim.memory_bytes = 4ULL << 30;
    const ChildResult r = run_child(sim_argv(t), lim, dir);
    if (!r.started || r.timed_out || r.signal != 0 || r.exit_code != 0)
      throw std::runtime_error("similarity: sim_c++ on the class's " + tasks_[t] + " " +
                               sim_failure(r, options_) +
                               (r.err.empty() ? "" : ": " + safe_excerpt(r.err, 400)));
  }

  // The submission a sim_c++ file name ("<i>.cpp") stands for, when it is one that was compared.
  bool copy_index(const std::string& name, std::size_t t, std::size_t& i) const {
    if (name.size() < 5 || name.compare(name.size() - 4, 4, ".cpp") != 0) return false;
    const std::string digits = name.substr(0, name.size() - 4);
    if (digits.empty() || digits.size() > 9 ||
        digits.find_first_not_of("0123456789") != std::string::npos)
      return false;
    i = std::stoul(digits);
    return i < inputs_.size() && copies_[i][t].present;
  }

  // Runs against the stub or the handout mark given code the student moved or reformatted; the
  // others are the shared regions.
  void read_runs(std::size_t t, const fs::path& dir) {
    std::istringstream simout(read_file(dir / "sim.out"));
    std::string line;
    while (std::getline(simout, line)) {
      SimLine s;
      if (!parse_sim_line(line, s)) continue;
      std::size_t a = 0, b = 0;
      const bool left = copy_index(s.left, t, a), right = copy_index(s.right, t, b);
      if (left && (s.right == "stub.cpp" || s.right.rfind("handout", 0) == 0)) {
        for (long n = s.l1; n <= s.l2 && n <= static_cast<long>(copies_[a][t].stub.size()); ++n)
          copies_[a][t].stub[static_cast<std::size_t>(n - 1)] = 1;
      } else if (left && right && a != b) {
        Run run{a, b, t, s.l1, s.l2, s.r1, s.r2, s.tokens};
        if (a > b) run = Run{b, a, t, s.r1, s.r2, s.l1, s.l2, s.tokens};
        runs_.push_back(run);
      }
    }
  }

  const GradeConfig& config_;
  const std::vector<SimilarityInput>& inputs_;
  const SimilarityOptions& options_;
  const fs::path sim_;
  const fs::path work_;
  const std::vector<std::string>& tasks_;
  std::vector<std::vector<TaskCopy>> copies_;
  std::vector<Run> runs_;
  const std::vector<std::string> handout_;
};

}  // namespace

fs::path similarity_tool() {
  const fs::path sim = find_on_path("sim_c++").value_or(fs::path());
  if (sim.empty())
    throw std::runtime_error(
        "similarity: sim_c++ (Dick Grune's similarity tester) was not found on PATH: install the "
        "Debian package similarity-tester (sudo apt-get install similarity-tester, or sudo "
        "tools/install-deps.sh)");
  return sim;
}

int write_similarity(const GradeConfig& config, const std::vector<SimilarityInput>& inputs,
                     const fs::path& out, const SimilarityOptions& options) {
  const fs::path sim = similarity_tool();
  fs::create_directories(out);
  const fs::path work = out / "similarity-work";
  struct RemoveWork {
    fs::path dir;
    ~RemoveWork() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  } remove_work{work};
  fs::remove_all(work);
  ClassComparison comparison(config, inputs, sim, work, options);
  comparison.compare_all();
  return comparison.write_report(out);
}

}  // namespace jelly::grade
