// The grading runner's harness: test cases as code, each calling ONE task's functions through the
// TaskTable of whatever task library the runner is linked with (the reference when generating
// reference data, a submission when grading). The orchestrator (jelly-grade) compares the named
// outputs a case emits with the stored reference; the runner itself never judges.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "jelly/cube.hpp"
#include "jelly/spring.hpp"
#include "jelly/world.hpp"
#include "jelly/task_table.hpp"
#include "jelly/types.hpp"

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
  const Json& json() const { return out_; }

 private:
  Json out_ = Json::object();
};

/// One test case. `prepare` (optional) builds the case's input with the REFERENCE tasks when the
/// reference data is generated (e.g. the reference spring list of a cube, which the framework does
/// not otherwise have); the input is stored with the reference data and handed to `run`.
struct CaseDef {
  std::string id;
  std::string description;
  std::function<void(const TaskTable& tasks, Json& input)> prepare;
  std::function<void(const TaskTable& tasks, const Json& input, Outputs& out)> run;
};

class Registry {
 public:
  void add(CaseDef def);
  const std::vector<CaseDef>& cases() const { return cases_; }
  const CaseDef* find(const std::string& id) const;

 private:
  std::vector<CaseDef> cases_;
};

// Registration, one function per task group (cases_*.cpp).
void register_spring_cases(Registry& r);
void register_force_cases(Registry& r);
void register_terrain_cases(Registry& r);
void register_integrator_cases(Registry& r);
void register_scene_cases(Registry& r);

// ----- helpers shared by the cases -----

/// The reference springs of a cube, as stored in a case input: [[a, b, rest], ...].
Json springs_to_json(const std::vector<Spring>& springs);
std::vector<Spring> springs_from_json(const Json& j);

/// The small cube the force-scene and linear-cube cases use: n = 3, edge 2, centred at (0, 5, 0),
/// rotated 20° about (1, 0, 1).
CubeSpec small_cube_spec();
/// prepare(): the REFERENCE springs of small_cube_spec(), per type, into input["springs"].
void prepare_small_cube_springs(const TaskTable& reference, Json& input);
/// Adds the small cube's particles and the spring groups stored in input["springs"] to a world,
/// every group with the given coefficients (no student builder involved).
void add_small_cube(World& world, const Json& input, double ks, double kd);

/// A deterministic pseudo-random sequence in [−1, 1) (its own arithmetic, so that every standard
/// library gives the same numbers).
class Sequence {
 public:
  explicit Sequence(std::uint64_t seed) : state_(seed * 6364136223846793005ULL + 1442695040888963407ULL) {}
  double next();

 private:
  std::uint64_t state_;
};

}  // namespace jelly::grade
