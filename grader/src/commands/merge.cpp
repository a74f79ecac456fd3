#include <iostream>
#include <map>
#include <set>
#include <stdexcept>

#include "class/class_record.hpp"
#include "class/csv.hpp"
#include "commands/commands.hpp"
#include "inputs/files.hpp"
#include "reports/text_safety.hpp"

namespace jelly::grade {

namespace {

Json read_batch_manifest(const fs::path& part) {
  const fs::path file = part / "batch.json";
  std::error_code ec;
  if (!fs::is_regular_file(file, ec))
    throw std::runtime_error(
        file.string() +
        " does not exist: expected the --out folder of a jelly-grade batch (a batch writes it "
        "when it ends: if this part was stopped, finish it with the same command and --resume)");
  Json m;
  try {
    m = Json::parse(read_file(file));
  } catch (const std::exception& e) {
    throw std::runtime_error(file.string() + ": not a batch manifest (" + e.what() + ")");
  }
  if (!m.is_object() || m.value("format", "") != "jelly-grade batch 1" || !m.contains("class") ||
      !m["class"].is_array() || !m.contains("students") || !m["students"].is_array())
    throw std::runtime_error(file.string() +
                             ": not a batch manifest (expected \"format\": \"jelly-grade batch "
                             "1\" with \"class\" and \"students\" lists)");
  return m;
}

/// Every part must come from the same class, graded the same way, and no student may be in two
/// parts. Returns who graded whom: student id → the part.
std::map<std::string, std::string> check_parts(const GradeConfig& config,
                                               const std::vector<std::string>& parts,
                                               const std::vector<Json>& manifests) {
  const Json& first = manifests.front();
  std::map<std::string, std::string> owner;  // student id → the part that graded them
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const Json& m = manifests[k];
    const std::string where = (fs::path(parts[k]) / "batch.json").string();
    if (m.value("assignment", "") != config.assignment().id)
      throw std::runtime_error(where + ": graded assignment '" + m.value("assignment", "") +
                               "', not '" + config.assignment().id + "'");
    if (m.value("fingerprint", "") != first.value("fingerprint", ""))
      throw std::runtime_error(
          where + " was graded differently from " + (fs::path(parts[0]) / "batch.json").string() +
          " (another grader build, reference data, rubric, visibility or --timeout): grade every "
          "part with the same command and the same build");
    if (m["class"] != first["class"])
      throw std::runtime_error(where + " lists another class than " +
                               (fs::path(parts[0]) / "batch.json").string() +
                               ": every shard must read the same submissions folder");
    for (const Json& id : m["students"]) {
      const std::string s = id.get<std::string>();
      if (const auto [it, added] = owner.emplace(s, parts[k]); !added)
        throw std::runtime_error("student '" + safe_text(s) + "' is in both " + it->second +
                                 " and " + parts[k] + ": were two parts given the same --shard?");
    }
  }
  return owner;
}

/// When the parts are shards of one count N, the shards that were not given ("2/4, 4/4");
/// otherwise "".
std::string shards_not_given(const std::vector<Json>& manifests) {
  std::set<std::string> given;
  std::string count;
  bool one_count = true;
  for (const Json& m : manifests) {
    const std::string shard = m.value("shard", "");
    const auto slash = shard.find('/');
    if (slash == std::string::npos) {
      one_count = false;
      continue;
    }
    if (!count.empty() && count != shard.substr(slash + 1)) one_count = false;
    count = shard.substr(slash + 1);
    given.insert(shard);
  }
  std::string shards;
  if (one_count && !count.empty() && count.size() < 6 &&
      count.find_first_not_of("0123456789") == std::string::npos) {
    const int n = std::stoi(count);
    for (int i = 1; i <= n; ++i)
      if (!given.count(shard_label(i, n)))
        shards += (shards.empty() ? "" : ", ") + shard_label(i, n);
  }
  return shards;
}

/// Every student of the class must be in a part: throws naming the missing ones (and shards).
void check_whole_class(const std::vector<Json>& manifests,
                       const std::map<std::string, std::string>& owner) {
  const Json& first = manifests.front();
  std::vector<std::string> missing;
  for (const Json& id : first["class"])
    if (!owner.count(id.get<std::string>())) missing.push_back(id.get<std::string>());
  if (missing.empty()) return;
  std::string list;
  for (std::size_t k = 0; k < missing.size() && k < 5; ++k)
    list += (k ? ", " : "") + safe_text(missing[k]);
  const std::string shards = shards_not_given(manifests);
  throw std::runtime_error(
      (shards.empty() ? std::string("a part is missing") : "shard " + shards + " is missing") +
      ": " + std::to_string(missing.size()) + " of the class's " +
      std::to_string(first["class"].size()) + " students are in none of the parts (" + list +
      (missing.size() > 5 ? ", ..." : "") +
      "); give every part's --out folder (the shard of a part is in its batch.json)");
}

/// Every part's records, in class order; each must be there and whole before anything is copied.
std::vector<Json> read_records(const Json& first, const std::map<std::string, std::string>& owner) {
  std::vector<Json> records;
  for (const Json& id : first["class"]) {
    const std::string s = id.get<std::string>();
    records.push_back(read_record(record_path(owner.at(s), s)));
    // A record regraded under other options after its part's batch.json was written (a later
    // batch into the same folder, stopped) is not this part's result.
    if (records.back().value("fingerprint", "") != first.value("fingerprint", ""))
      throw std::runtime_error(record_path(owner.at(s), s).string() +
                               " was graded differently from its part's batch.json (another "
                               "batch into " +
                               owner.at(s) + " was stopped?): finish that part with --resume");
  }
  return records;
}

/// Each student's folder into out/students/, whole or not at all; and batch --similarity's
/// report (the first shard compared the whole class).
void copy_results(const std::vector<std::string>& parts,
                  const std::map<std::string, std::string>& owner, const fs::path& out) {
  fs::create_directories(out / "students");
  for (const auto& [id, part] : owner) {
    const fs::path from = fs::path(part) / "students" / id;
    const fs::path to = out / "students" / id;
    std::error_code ec;
    if (fs::equivalent(from, to, ec)) continue;
    const fs::path tmp = out / "students" / ("." + id + ".partial");
    fs::remove_all(tmp);
    fs::copy(from, tmp, fs::copy_options::recursive);
    fs::remove_all(to);
    fs::rename(tmp, to);
  }
  for (const std::string& p : parts)
    for (const char* name : {"similarity.html", "similarity.json"}) {
      const fs::path from = fs::path(p) / name;
      std::error_code ec;
      if (fs::is_regular_file(from, ec) && !fs::equivalent(from, out / name, ec))
        write_file_atomically(out / name, read_file(from));
    }
}

}  // namespace

std::string batch_assignment(const fs::path& part) {
  return read_batch_manifest(part).value("assignment", "");
}

int merge(const GradeConfig& config, const CaseBook& book, const std::vector<std::string>& parts,
          const fs::path& out) {
  if (parts.empty()) throw std::runtime_error("merge: no batch folders given");
  std::vector<Json> manifests;
  for (const std::string& p : parts) manifests.push_back(read_batch_manifest(p));
  const Json& first = manifests.front();
  const std::map<std::string, std::string> owner = check_parts(config, parts, manifests);
  check_whole_class(manifests, owner);
  const std::vector<Json> records = read_records(first, owner);
  copy_results(parts, owner, out);
  Json manifest = first;
  manifest["shard"] = "1/1";
  manifest["students"] = first["class"];
  write_file_atomically(out / "batch.json", manifest.dump(2) + "\n");
  write_class_files(out, records, book, config.assignment().manifest.title);
  int status = 0;
  for (const Json& r : records)
    if (r.value("status", "") != "graded") status = 1;
  std::cout << "jelly-grade: merged " << parts.size() << " parts (" << records.size()
            << " students) into " << out.string() << "\n";
  return status;
}

}  // namespace jelly::grade
