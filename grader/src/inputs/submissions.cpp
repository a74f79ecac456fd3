#include "inputs/submissions.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <stdexcept>

#include "inputs/class_archives.hpp"
#include "inputs/files.hpp"
#include "reports/text_safety.hpp"
#include "sandbox/process.hpp"

namespace jelly::grade {

namespace fs = std::filesystem;

namespace {

constexpr const char* kMetadata = "submission_metadata.yml";

/// Text without the blanks around it.
std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

// ---------------------------------------------------------------------------------------------
// Folders, symlinks, ids.

bool ignored_entry(const std::string& name) {
  // Hidden files (.DS_Store, .git) and macOS's zip noise.
  return name.empty() || name[0] == '.' || name == "__MACOSX";
}

/// `p` lies inside `root` (both lexically normal and absolute).
bool inside(const fs::path& p, const fs::path& root) {
  auto r = root.begin();
  auto q = p.begin();
  for (; r != root.end(); ++r, ++q) {
    if (r->empty()) continue;  // a trailing separator
    if (q == p.end() || *q != *r) return false;
  }
  return true;
}

/// Whether the symlink `link` (inside `root`) points inside `root`, both as its text says and as
/// the file system resolves it.
bool link_stays_inside(const fs::path& link, const fs::path& root) {
  std::error_code ec;
  const fs::path target = fs::read_symlink(link, ec);
  if (ec) return false;
  const fs::path lexical =
      (target.is_absolute() ? target : link.parent_path() / target).lexically_normal();
  if (!inside(lexical, root.lexically_normal())) return false;
  const fs::path real = fs::weakly_canonical(link, ec);
  if (ec) return false;
  const fs::path real_root = fs::weakly_canonical(root, ec);
  return !ec && inside(real, real_root);
}

/// Why the folder `dir` (a submission, inside `root`, the class) cannot be graded, or "";
/// `notes` gets the symlinks inside it that lead out of it (never followed: the build reads no task
/// file through a link and reports such a file, so the rest of the submission is graded).
std::string folder_problem(const fs::path& dir, const fs::path& root,
                           std::vector<std::string>& notes) {
  std::error_code ec;
  if (fs::symlink_status(dir, ec).type() == fs::file_type::symlink) {
    if (!link_stays_inside(dir, root))
      return "the folder is a symlink to " + fs::read_symlink(dir, ec).string() +
             ", outside the class's folder: not followed";
  }
  std::size_t files = 0;
  for (fs::recursive_directory_iterator it(dir, fs::directory_options::none, ec), end;
       !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    const fs::file_type type = it->symlink_status(ec).type();
    if (type == fs::file_type::directory && name == ".git") {
      it.disable_recursion_pending();
      continue;
    }
    if (type == fs::file_type::symlink) {
      if (!link_stays_inside(it->path(), dir))
        notes.push_back(it->path().lexically_relative(dir).generic_string() + " is a symlink to " +
                        fs::read_symlink(it->path(), ec).string() +
                        ", outside the submission: not followed (the build refuses a task "
                        "file that is a link: its tasks score 0)");
      continue;
    }
    if (type == fs::file_type::regular) ++files;
  }
  if (ec) return "its files cannot be read: " + ec.message();
  if (files == 0) return "an empty folder: there is no file to grade";
  return "";
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

struct Entry {
  fs::path path;    ///< in the class
  std::string key;  ///< the name in the class (folder, file)
};

/// The visible entries of `root` in name order.
std::vector<Entry> entries_of(const fs::path& root, const std::set<std::string>& skip = {}) {
  std::vector<Entry> out;
  for (const auto& e : fs::directory_iterator(root)) {
    const std::string n = e.path().filename().string();
    if (ignored_entry(n) || skip.count(n)) continue;
    out.push_back({e.path(), n});
  }
  std::sort(out.begin(), out.end(), [](const Entry& a, const Entry& b) { return a.key < b.key; });
  return out;
}

bool is_folder(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);  // follows a symlink: folder_problem judges the link itself
}

/// The longest prefix ending in '-' every name starts with (GitHub Classroom's
/// "<assignment>-"), leaving each name at least one character.
std::string common_dash_prefix(const std::vector<Entry>& es) {
  if (es.empty()) return "";
  std::string p = es.front().key;
  for (const Entry& e : es) {
    std::size_t k = 0;
    while (k < p.size() && k < e.key.size() && p[k] == e.key[k]) ++k;
    p.resize(k);
  }
  for (const Entry& e : es)
    if (p.size() >= e.key.size()) p.resize(e.key.size() - 1);
  const auto dash = p.rfind('-');
  return dash == std::string::npos ? "" : p.substr(0, dash + 1);
}

/// Why the zip entry `name` is refused ("an absolute path", "a '..' component", both; "" when it is
/// not), and `landing`: where unzip's own sanitising puts it (it strips a leading '/' and a drive,
/// and drops ".." components), relative to the folder it extracts into.
std::string refusal_of(const std::string& name, fs::path& landing) {
  std::string why;
  std::string rest = name;
  if (rest.size() >= 2 && std::isalpha(static_cast<unsigned char>(rest[0])) && rest[1] == ':') {
    why = "an absolute path";
    rest = rest.substr(2);
  }
  if (!rest.empty() && (rest[0] == '/' || rest[0] == '\\')) why = "an absolute path";
  std::string part;
  for (std::size_t k = 0; k <= rest.size(); ++k) {
    if (k == rest.size() || rest[k] == '/' || rest[k] == '\\') {
      if (part == ".." && why.find("'..'") == std::string::npos)
        why = why.empty() ? "a '..' component" : why + " and a '..' component";
      else if (part == "..")
        ;
      else if (!part.empty() && part != ".")
        landing /= part;
      part.clear();
    } else {
      part += rest[k];
    }
  }
  return why;
}

/// Extracts `zip` into `scratch` with unzip, its entries listed with libzip. Entries with an
/// absolute path or a ".." component are refused: returned as (where unzip's own sanitising puts
/// them, relative to `scratch`, the message); unzip itself keeps every file inside `scratch` and
/// makes symlinks last, so that no entry is written through one.
std::vector<std::pair<fs::path, std::string>> extract_zip(const fs::path& zip,
                                                          const fs::path& scratch) {
  std::error_code ec;
  fs::remove_all(scratch, ec);
  fs::create_directories(scratch);
  const std::string shown = zip.filename().string();
  const Limits lim = trusted_tool_limits(600.0, std::size_t{256} << 20);
  const std::string unzip = find_on_path("unzip").value_or("/usr/bin/unzip").string();
  std::vector<std::pair<fs::path, std::string>> refused;
  for (const std::string& name : zip_entry_names(zip, shown)) {
    if (name.empty()) continue;
    fs::path landing;
    const std::string why = refusal_of(name, landing);
    if (!why.empty())
      refused.emplace_back(landing, "the zip's entry '" + name + "' has " + why +
                                        ": refused (it could write outside the export)");
  }
  const ChildResult x = run_child({unzip, "-qq", "-o", zip.string(), "-d", scratch.string()}, lim);
  // 1: warnings (such as the refused names unzip sanitised); 2: an error in some entry, the rest
  // extracted. Worse: nothing to trust.
  if (!x.started || x.timed_out || x.exit_code < 0 || x.exit_code > (refused.empty() ? 1 : 2))
    throw std::runtime_error(shown + ": unzip could not extract it (exit status " +
                             std::to_string(x.exit_code) + (x.timed_out ? ", timed out" : "") +
                             "): " + trim(x.err + x.out));
  // What unzip made of a refused entry is not the student's file: it goes.
  for (const auto& r : refused)
    if (!r.first.empty() &&
        fs::symlink_status(scratch / r.first, ec).type() != fs::file_type::directory)
      fs::remove(scratch / r.first, ec);
  return refused;
}

// ---------------------------------------------------------------------------------------------
// Learning-management systems' bulk downloads: Canvas's "Download Submissions" (one flat folder of
// files) and Moodle's "Download all submissions" (a folder per student and plugin, or flat files).

/// What one entry of an LMS download says about its student.
struct LmsEntry {
  std::string system;  ///< "Canvas" or "Moodle"
  std::string id;      ///< Canvas's user id ("anon_<id>" when anonymous), Moodle's participant id
  std::string name;    ///< as the file name gives it ("smithjane"; "Jane Smith"); "" if anonymous
  bool late = false;   ///< Canvas's LATE mark
};

/// The student an entry of an LMS download belongs to, from its name alone; nullopt when the name
/// is no such name. Canvas (lib/content_zipper.rb) names an uploaded file
/// `<name>[_LATE]_<user id>_<file id>_<file>` (name: the sortable name, lower case, letters and
/// digits only; LATE in upper case today, `late` in older downloads), a text entry
/// `<name>[_LATE]_<user id>_text.html`, and for an anonymous assignment `[LATE_]anon_<id>_...`.
/// Moodle (mod/assign, downloader.php) names a student's folder `<Full Name>_<participant
/// id>_assignsubmission_<plugin>` (Moodle 4.1 on; a trailing '_' before), and, downloading
/// without folders, each file `<Full Name>_<participant id>_assignsubmission_<plugin>_<file>`.
std::optional<LmsEntry> lms_entry(const std::string& n, bool folder) {
  static const std::regex moodle_folder(R"(^(.+)_([0-9]+)_assignsubmission_[a-z0-9]+_?$)");
  static const std::regex moodle_file(R"(^(.+)_([0-9]+)_assignsubmission_[a-z0-9]+_.+$)");
  static const std::regex canvas_anon(R"(^(?:(LATE|late)_)?anon_([A-Za-z0-9]+)_[0-9]+_.+$)");
  static const std::regex canvas(
      R"(^(.+?)(_LATE|_late)?_([0-9]+)_(?:[0-9]+_.+|text\.html|link\.html)$)");
  std::smatch m;
  if (folder) {
    if (std::regex_match(n, m, moodle_folder)) return LmsEntry{"Moodle", m[2], m[1], false};
    return std::nullopt;
  }
  if (std::regex_match(n, m, moodle_file)) return LmsEntry{"Moodle", m[2], m[1], false};
  if (std::regex_match(n, m, canvas_anon))
    return LmsEntry{"Canvas", "anon_" + m[2].str(), "", m[1].matched};
  if (std::regex_match(n, m, canvas)) return LmsEntry{"Canvas", m[3], m[1], m[2].matched};
  return std::nullopt;
}

/// Whether `entries` (a class's top level) is an LMS download: an entry named as one names it.
bool is_lms_download(const std::vector<Entry>& entries) {
  for (const Entry& e : entries)
    if (lms_entry(e.key, is_folder(e.path))) return true;
  return false;
}

/// One student of an LMS download: the entries named as theirs.
struct LmsStudent {
  LmsEntry who;
  std::vector<const Entry*> entries;
  std::set<std::string> names;
  std::string problem;
};

/// An entry named as a download's: why the class is read as one.
std::string lms_witness(const std::vector<Entry>& entries) {
  std::string witness;
  for (const Entry& e : entries)
    if (witness.empty() && lms_entry(e.key, is_folder(e.path))) witness = e.key;
  return witness;
}

/// The row, not graded, of an entry named as no student's.
Submission stray_lms_entry(const Entry& e, bool folder, const std::string& witness) {
  Submission s;
  s.id = e.key;
  s.source = e.key;
  s.dir = e.path;
  s.problem = "'" + e.key + "' is " + (folder ? "a folder" : "a file") +
              " of a Canvas or Moodle download not named as these name a student's entry "
              "(Canvas: <name>_<user id>_<file id>_<file>; Moodle: <Full "
              "Name>_<participant id>_assignsubmission_file): it belongs to no student "
              "(the class is read as such a download because '" +
              witness + "' is named as one)";
  return s;
}

/// Gives entry e, named as `who`'s, to its student.
void add_lms_entry(LmsStudent& st, const LmsEntry& who, const Entry& e, const fs::path& root,
                   const std::map<std::string, std::vector<std::string>>& refused_in) {
  std::error_code ec;
  if (st.entries.empty()) st.who = who;
  st.who.late = st.who.late || who.late;
  st.entries.push_back(&e);
  st.names.insert(who.name);
  if (const auto r = refused_in.find(e.key); r != refused_in.end() && st.problem.empty())
    st.problem = r->second.front();
  // A folder that is a symlink out of the class, or a file that is one: never followed.
  if (fs::symlink_status(e.path, ec).type() == fs::file_type::symlink &&
      !link_stays_inside(e.path, root) && st.problem.empty())
    st.problem = "'" + e.key + "' is a symlink to " + fs::read_symlink(e.path, ec).string() +
                 ", outside the class's folder: not followed";
}

/// What the download says of the student: their entries, their names, a late mark.
std::vector<std::string> lms_notes(const LmsStudent& st) {
  std::vector<std::string> notes;
  std::string listed;
  for (const Entry* e : st.entries) listed += (listed.empty() ? "" : ", ") + e->key;
  notes.push_back(st.who.system + " download: " + listed + " (the id is " +
                  (st.who.system == "Canvas" ? "Canvas's user id, the gradebook export's ID"
                                             : "Moodle's participant id, the grading "
                                               "worksheet's Identifier") +
                  ")");
  if (st.names.size() > 1) {
    std::string all;
    for (const std::string& n : st.names) all += (all.empty() ? "" : ", ") + n;
    notes.push_back("the files of " + st.who.id + " give several names: " + all);
  }
  if (st.who.late) notes.push_back("Canvas marked the submission late (LATE in its names)");
  return notes;
}

/// Copies the student's entries into s.dir (created), under the names the download gave them,
/// until one cannot be read.
void copy_lms_entries(const LmsStudent& st, Submission& s) {
  std::error_code ec;
  fs::create_directories(s.dir, ec);
  for (const Entry* e : st.entries) {
    if (!s.problem.empty()) break;
    const bool folder = is_folder(e->path);
    if (!folder && lower(e->path.extension().string()) == ".zip")
      s.notes.push_back(e->key +
                        " is a zip the student handed in: it is not unpacked, so no "
                        "file inside it is graded");
    fs::copy(e->path, s.dir / e->key, fs::copy_options::recursive | fs::copy_options::copy_symlinks,
             ec);
    if (ec) s.problem = "'" + e->key + "' cannot be read: " + ec.message();
  }
}

/// The student's row, their entries gathered in `dir`.
Submission lms_submission(const LmsStudent& st, const fs::path& dir) {
  Submission s;
  s.id = st.who.id;
  s.name = st.who.name;
  s.source = st.entries.front()->key;
  s.dir = dir;
  s.notes = lms_notes(st);
  s.problem = st.problem;
  copy_lms_entries(st, s);
  if (s.problem.empty()) s.problem = folder_problem(s.dir, s.dir, s.notes);
  return s;
}

/// The students of an LMS download, one per (system, id), each given a folder under `gather`
/// (emptied first) holding copies of their entries under the names the download gave them (the
/// build takes Canvas's and Moodle's file names for the task files they stand for, the latest
/// resubmission first). An entry named as no student's becomes a row of its own that is not
/// graded, saying why.
std::vector<Submission> lms_submissions(
    const std::vector<Entry>& entries, const fs::path& root, const fs::path& gather,
    const std::map<std::string, std::vector<std::string>>& refused_in) {
  std::error_code ec;
  fs::remove_all(gather, ec);
  std::map<std::pair<std::string, std::string>, LmsStudent> students;
  std::vector<Submission> subs;
  const std::string witness = lms_witness(entries);
  for (const Entry& e : entries) {
    const bool folder = is_folder(e.path);
    if (const std::optional<LmsEntry> who = lms_entry(e.key, folder))
      add_lms_entry(students[{who->system, who->id}], *who, e, root, refused_in);
    else
      subs.push_back(stray_lms_entry(e, folder, witness));
  }
  std::size_t k = 0;
  for (const auto& [key, st] : students)
    subs.push_back(lms_submission(st, gather / std::to_string(++k)));
  return subs;
}

}  // namespace

std::string safe_id(const std::string& raw) {
  std::string s;
  for (unsigned char c : raw) {
    if (c < 0x20 || c == 0x7F || c == '/' || c == '\\' || c == '<' || c == '>' || c == ':' ||
        c == '"' || c == '|' || c == '?' || c == '*')
      s += '_';
    else
      s += static_cast<char>(c);
  }
  while (!s.empty() && (s.back() == ' ' || s.back() == '.')) s.pop_back();  // Windows drops them
  if (!s.empty() && (s[0] == '.' || s[0] == ' ' || s[0] == '-')) s.insert(s.begin(), '_');
  if (s.size() > 100) {
    s.resize(100);
    while (!s.empty() && (static_cast<unsigned char>(s.back()) & 0xC0) == 0x80) s.pop_back();
    if (!s.empty() && (static_cast<unsigned char>(s.back()) & 0x80)) s.pop_back();
  }
  // Names Windows reserves for devices, whatever the extension.
  static const std::set<std::string> devices = {
      "con",  "prn",  "aux",  "nul",  "com1", "com2", "com3", "com4", "com5", "com6", "com7",
      "com8", "com9", "lpt1", "lpt2", "lpt3", "lpt4", "lpt5", "lpt6", "lpt7", "lpt8", "lpt9"};
  if (devices.count(lower(s.substr(0, s.find('.'))))) s.insert(s.begin(), '_');
  if (s.empty()) s = "_";
  return s;
}

namespace {

// The folder whose entries are the class's submissions: `in`, or the zip extracted into `scratch`
// (`refused` gets the entries refused by name), or the one Gradescope export or LMS download
// folder inside either.
fs::path class_root(const fs::path& in, const fs::path& scratch,
                    std::vector<std::pair<fs::path, std::string>>& refused) {
  std::error_code ec;
  fs::path root = in;
  if (fs::is_regular_file(in, ec)) {
    if (lower(in.extension().string()) != ".zip")
      throw std::runtime_error(in.string() +
                               ": expected a folder of submissions or a .zip (a Gradescope "
                               "export, or Canvas's or Moodle's download), found a file");
    if (scratch.empty())
      throw std::runtime_error(in.string() + ": a zip needs a scratch folder to be extracted into");
    refused = extract_zip(in, scratch);
    root = scratch;
  } else if (!fs::is_directory(in, ec)) {
    throw std::runtime_error(in.string() + ": no such folder or .zip");
  }
  // A Gradescope export zipped whole (assignment_123_export/submission_metadata.yml ...).
  if (!fs::exists(root / kMetadata, ec)) {
    std::vector<fs::path> exports;
    for (const Entry& e : entries_of(root))
      if (fs::symlink_status(e.path, ec).type() == fs::file_type::directory &&
          fs::is_regular_file(e.path / kMetadata, ec))
        exports.push_back(e.path);
    if (exports.size() == 1) root = exports.front();
  }
  // A Canvas or Moodle download zipped or unpacked into one folder of its own.
  if (!fs::exists(root / kMetadata, ec)) {
    const std::vector<Entry> top = entries_of(root);
    if (top.size() == 1 &&
        fs::symlink_status(top.front().path, ec).type() == fs::file_type::directory &&
        !is_lms_download(top) && is_lms_download(entries_of(top.front().path)))
      root = top.front().path;
  }
  return root;
}

// The refused zip entries by the submission folder each would have landed in; those that name no
// submission folder go to `warnings`.
std::map<std::string, std::vector<std::string>> refused_by_entry(
    const fs::path& in, const fs::path& root, const fs::path& scratch,
    const std::vector<std::pair<fs::path, std::string>>& refused, const std::vector<Entry>& entries,
    std::vector<std::string>* warnings) {
  const fs::path rel_root = root == scratch ? fs::path() : root.lexically_relative(scratch);
  std::map<std::string, std::vector<std::string>> refused_in;
  for (const auto& [landing, message] : refused) {
    const fs::path rel = rel_root.empty() ? landing : landing.lexically_relative(rel_root);
    const std::string first = rel.empty() ? "" : rel.begin()->string();
    bool owner = false;
    for (const Entry& e : entries)
      if (!first.empty() && first != ".." && e.key == first) owner = true;
    if (owner)
      refused_in[first].push_back(message);
    else if (warnings)
      warnings->push_back(in.filename().string() + ": " + message +
                          "; it names no submission folder, so no student's grade depends on it");
  }
  return refused_in;
}

// One entry of the class as a submission (its id still to be given): its problem, if any.
Submission from_entry(const Entry& e, const fs::path& root,
                      const std::map<std::string, std::vector<std::string>>& refused_in) {
  Submission s;
  s.source = e.key;
  s.dir = e.path;
  if (!is_folder(e.path))
    s.problem = "'" + e.key +
                "' is a file, not a folder: each submission is a folder of files (a student's "
                "zip must be unpacked first), unless the class is a Canvas or Moodle download, "
                "whose files are named after their students";
  else if (const auto r = refused_in.find(e.key); r != refused_in.end())
    s.problem = r->second.front();
  else
    s.problem = folder_problem(e.path, root, s.notes);
  return s;
}

// A Gradescope export: one row per submitter of each submission submission_metadata.yml lists
// (id: the :sid:, else the email, else the folder), and one per folder it does not list.
std::vector<Submission> gradescope_submissions(
    const fs::path& in, const fs::path& scratch, const fs::path& root,
    const std::vector<Entry>& entries,
    const std::map<std::string, std::vector<std::string>>& refused_in) {
  std::error_code ec;
  std::vector<Submission> subs;
  const std::vector<GradescopeEntry> meta = read_gradescope_metadata(
      read_file(root / kMetadata),
      fs::is_regular_file(in, ec) ? in.filename().string() + ": " +
                                        fs::relative(root / kMetadata, scratch, ec).generic_string()
                                  : (root / kMetadata).string());
  std::map<std::string, const Entry*> by_folder;
  for (const Entry& e : entries) by_folder[e.key] = &e;
  std::set<std::string> listed;
  for (const GradescopeEntry& g : meta) {
    listed.insert(g.folder);
    const auto f = by_folder.find(g.folder);
    Submission base;
    if (f == by_folder.end()) {
      base.source = g.folder;
      base.dir = root / safe_id(g.folder);
      base.problem = std::string(kMetadata) + " lists the submission " + g.folder + " (line " +
                     std::to_string(g.line) + ") but the export has no such folder";
    } else {
      base = from_entry(*f->second, root, refused_in);
    }
    if (g.submitters.empty()) {
      Submission s = base;
      s.id = g.folder;
      s.notes.push_back(std::string(kMetadata) + " names no submitter for " + g.folder +
                        ": the id is the folder's name");
      subs.push_back(s);
      continue;
    }
    for (std::size_t k = 0; k < g.submitters.size(); ++k) {
      const GradescopeSubmitter& who = g.submitters[k];
      Submission s = base;
      s.name = who.name;
      s.email = who.email;
      if (!who.sid.empty()) {
        s.id = who.sid;
      } else if (!who.email.empty()) {
        s.id = who.email;
        s.notes.push_back("no student id (:sid:) in " + std::string(kMetadata) + " for " +
                          (who.name.empty() ? g.folder : who.name) + ": the id is the email");
      } else {
        s.id = g.folder;
        s.notes.push_back("neither a student id (:sid:) nor an email in " + std::string(kMetadata) +
                          " for " + (who.name.empty() ? g.folder : who.name) +
                          ": the id is the submission folder's name");
      }
      if (g.submitters.size() > 1) {
        std::string others;
        for (std::size_t o = 0; o < g.submitters.size(); ++o)
          if (o != k) {
            const GradescopeSubmitter& w = g.submitters[o];
            others += (others.empty() ? "" : ", ") +
                      (w.name.empty() ? (w.sid.empty() ? w.email : w.sid) : w.name) +
                      (w.sid.empty() ? "" : " (" + w.sid + ")");
          }
        s.notes.push_back("group submission " + g.folder + " with " + others +
                          ": each member has a row, graded from the same files");
      }
      subs.push_back(s);
    }
  }
  for (const Entry& e : entries)
    if (!listed.count(e.key)) {
      Submission s = from_entry(e, root, refused_in);
      s.id = e.key;
      s.notes.push_back(e.key + " is not in " + std::string(kMetadata) +
                        ": the id is the folder's name");
      subs.push_back(s);
    }
  return subs;
}

// A folder of student folders (id: the folder's name), or of GitHub Classroom clones (id: the
// username, the prefix every folder shares stripped).
std::vector<Submission> folder_submissions(
    const fs::path& in, const fs::path& root, const std::vector<Entry>& entries,
    const std::map<std::string, std::vector<std::string>>& refused_in) {
  std::error_code ec;
  std::vector<Submission> subs;
  // GitHub Classroom: every folder a git clone named <assignment>-<username>.
  bool classroom = !entries.empty();
  for (const Entry& e : entries)
    classroom = classroom && is_folder(e.path) && fs::exists(e.path / ".git", ec);
  std::string prefix;
  if (classroom) {
    // `gh classroom clone student-repos` clones into <assignment>-submissions/: its name says
    // where the username starts even when usernames share a start.
    const std::string parent =
        (fs::absolute(in).lexically_normal() / "").parent_path().filename().string();
    const std::string suffix = "-submissions";
    if (parent.size() > suffix.size() &&
        parent.compare(parent.size() - suffix.size(), suffix.size(), suffix) == 0) {
      prefix = parent.substr(0, parent.size() - suffix.size()) + "-";
      for (const Entry& e : entries)
        if (e.key.rfind(prefix, 0) != 0 || e.key.size() == prefix.size()) prefix.clear();
    }
    if (prefix.empty()) prefix = common_dash_prefix(entries);
  }
  for (const Entry& e : entries) {
    Submission s = from_entry(e, root, refused_in);
    s.id = e.key;
    if (!prefix.empty()) {
      s.id = e.key.substr(prefix.size());
      s.notes.push_back("GitHub Classroom repository " + e.key + ": the id is the username " +
                        s.id + " (the prefix " + prefix + " every folder shares stripped)");
    }
    subs.push_back(s);
  }
  return subs;
}

// The ids made safe as folder names and unique whatever the case (students/<id> on a
// case-insensitive file system): a shared id grades none of its rows and names the others.
void settle_ids(std::vector<Submission>& subs) {
  for (Submission& s : subs) {
    const std::string safe = safe_id(s.id);
    if (safe != s.id) {
      s.notes.push_back("the id '" + s.id + "' is not safe as a folder name: it is " + safe);
      s.id = safe;
    }
  }
  std::stable_sort(subs.begin(), subs.end(),
                   [](const Submission& a, const Submission& b) { return a.id < b.id; });
  std::map<std::string, std::vector<std::size_t>> by_id;
  for (std::size_t k = 0; k < subs.size(); ++k) by_id[lower(subs[k].id)].push_back(k);
  std::set<std::string> taken;
  for (const Submission& s : subs) taken.insert(lower(s.id));
  for (const auto& [id, group] : by_id) {
    if (group.size() < 2) continue;
    for (std::size_t a = 0; a < group.size(); ++a) {
      Submission& s = subs[group[a]];
      std::string others;
      for (std::size_t b = 0; b < group.size(); ++b)
        if (b != a) others += (others.empty() ? "" : ", ") + subs[group[b]].source;
      const std::string was = s.id;
      if (s.problem.empty())
        s.problem = "the id " + was + " is also the id of " + others +
                    ": not graded, so that no student gets another's grade (fix the ids and "
                    "grade again)";
      if (a > 0) {
        int n = 2;
        std::string fresh;
        do fresh = was + "~" + std::to_string(n++);
        while (taken.count(lower(fresh)));
        taken.insert(lower(fresh));
        s.notes.push_back("the id " + was + " is taken: this row's id is " + fresh);
        s.id = fresh;
      }
    }
  }
  std::stable_sort(subs.begin(), subs.end(),
                   [](const Submission& a, const Submission& b) { return a.id < b.id; });
}

}  // namespace

std::vector<Submission> find_submissions(const fs::path& in, const fs::path& scratch,
                                         std::vector<std::string>* warnings) {
  std::error_code ec;
  std::vector<std::pair<fs::path, std::string>> refused;
  const fs::path root = class_root(in, scratch, refused);
  const bool gradescope = fs::is_regular_file(root / kMetadata, ec);
  std::vector<Entry> entries =
      entries_of(root, gradescope ? std::set<std::string>{kMetadata} : std::set<std::string>{});
  const std::map<std::string, std::vector<std::string>> refused_in =
      refused_by_entry(in, root, scratch, refused, entries, warnings);
  std::vector<Submission> subs;
  if (gradescope) {
    subs = gradescope_submissions(in, scratch, root, entries, refused_in);
  } else if (is_lms_download(entries)) {
    if (scratch.empty())
      throw std::runtime_error(in.string() +
                               ": a Canvas or Moodle download needs a scratch folder to gather "
                               "each student's files in");
    subs = lms_submissions(entries, root, scratch / ".by-student", refused_in);
  } else {
    subs = folder_submissions(in, root, entries, refused_in);
  }
  settle_ids(subs);
  return subs;
}

}  // namespace jelly::grade
