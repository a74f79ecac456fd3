// The grading runner's harness: test cases as code, each calling ONE task's functions through the
// TaskTable of whatever task library the runner is linked with (the reference when generating
// reference data, a submission when grading). The orchestrator (jelly-grade) compares the named
// outputs a case emits with the stored reference; the runner itself never judges.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "jelly/spring.hpp"
#include "jelly/task_table.hpp"
#include "jelly/types.hpp"
#include "jelly/world.hpp"

namespace jelly::grade {

using Json = nlohmann::ordered_json;

/// Named numeric (or text) outputs of one case, in the order they were emitted.
class Outputs {
 public:
  /// One number; `note` says in the student's terms what it is (shown when it does not match).
  void value(const std::string& name, double v, const std::string& note = {});
  /// A 3-vector (x, y, z).
  void vec(const std::string& name, const Vec3& v, const std::string& note = {});
  /// Several numbers (a trajectory, a list of errors, ...).
  void values(const std::string& name, const std::vector<double>& v, const std::string& note = {});
  /// Every column of a 3×N array, column after column.
  void array(const std::string& name, const Vec3Array& a, const std::string& note = {});
  /// A string compared exactly (a hash of a spring list).
  void text(const std::string& name, const std::string& v, const std::string& note = {});
  /// What the student's value of output `name` is made of, shown after its failure message: `low`
  /// when the value is below the reference's (e.g. which springs are missing), `high` when above
  /// (which ones are extra). Never stored as reference data, never compared.
  void detail(const std::string& name, const std::string& low, const std::string& high);
  const Json& json() const { return out_; }

 private:
  Json out_ = Json::object();
};

/// The parameters of one case: the `params` table of its [[case]] in
/// assignments/<id>/grader/cases/*.toml, handed to the runner by the orchestrator. Every input a
/// case feeds the student's code is made from these (and from framework presets), so a case's
/// inputs live in data, not in this code: removing a case from the case files removes every trace
/// of it. Reading a missing or mistyped key throws, naming the key and what was expected.
class Params {
 public:
  explicit Params(Json j, std::string path = "params") : j_(std::move(j)), path_(std::move(path)) {}
  bool has(const std::string& key) const { return j_.is_object() && j_.contains(key); }
  double number(const std::string& key) const;
  double number(const std::string& key, double fallback) const {
    return has(key) ? number(key) : fallback;
  }
  long integer(const std::string& key) const;
  long integer(const std::string& key, long fallback) const {
    return has(key) ? integer(key) : fallback;
  }
  std::string text(const std::string& key) const;
  std::string text(const std::string& key, const std::string& fallback) const {
    return has(key) ? text(key) : fallback;
  }
  Vec3 vec(const std::string& key) const;
  /// An array of numbers (e.g. the times at which to record frames).
  std::vector<double> numbers(const std::string& key) const;
  Vec3 vec(const std::string& key, const Vec3& fallback) const {
    return has(key) ? vec(key) : fallback;
  }
  Params table(const std::string& key) const;
  /// The elements of an array of tables (e.g. a list of hand-made springs).
  std::vector<Params> list(const std::string& key) const;
  const Json& json() const { return j_; }

 private:
  const Json& at(const std::string& key) const;
  [[noreturn]] void wrong(const std::string& key, const char* expected) const;
  Json j_;
  std::string path_;
};

/// One case generator: a family of tests (e.g. "a spring builder on a lattice"), turned into one
/// case by its parameters. `prepare` (optional) builds the case's input with the REFERENCE tasks
/// when the reference data is generated (e.g. the reference spring list of a body, which the
/// framework does not otherwise have); the input is stored with the reference data and handed to
/// `run`.
struct GeneratorDef {
  std::string name;
  std::string description;
  std::function<void(const TaskTable& tasks, const Params& params, Json& input)> prepare;
  std::function<void(const TaskTable& tasks, const Params& params, const Json& input, Outputs& out)>
      run;
};

class Registry {
 public:
  void add(GeneratorDef def);
  const std::vector<GeneratorDef>& generators() const { return generators_; }
  const GeneratorDef* find(const std::string& name) const;

 private:
  std::vector<GeneratorDef> generators_;
};

/// What an assignment's grader cases define, once, in assignments/<id>/grader/runner/ (the runner
/// of that assignment links them): register every case generator of the assignment.
void register_assignment_cases(Registry& r);
/// ... and the task table the cases test: the assignment's bindings over whichever implementation
/// the runner is linked with (the reference, the stubs or a submission).
TaskTable assignment_task_table();

// ----- helpers shared by the cases -----

/// Reference springs as stored in a case input: [[a, b, rest], ...].
Json springs_to_json(const std::vector<Spring>& springs);
std::vector<Spring> springs_from_json(const Json& j);

/// A deterministic pseudo-random sequence in [−1, 1) (its own arithmetic, so that every standard
/// library gives the same numbers).
class Sequence {
 public:
  explicit Sequence(std::uint64_t seed)
      : state_(seed * 6364136223846793005ULL + 1442695040888963407ULL) {}
  double next();
  /// Three draws as (x, y, z): z first, then y, then x. The reference data was made with
  /// `Vec3(r.next(), r.next(), r.next())`, whose arguments GCC on x86-64 evaluates last to first;
  /// C++ leaves that order unspecified and GCC on aarch64 goes first to last (issue 22), so the
  /// order is spelled out here.
  Vec3 next3();

 private:
  std::uint64_t state_;
};

}  // namespace jelly::grade
