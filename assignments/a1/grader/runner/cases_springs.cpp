// A1.T1–T3 cases: the student's builders on lattices the framework makes. Nothing here knows how
// to build springs: the cases classify what the builder returned (by grid offset, duplicates,
// indices, rest lengths) and the orchestrator compares that with the reference's classification.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

#include "cases.hpp"
#include "jelly/cube.hpp"
#include "jelly/cube_tasks.hpp"

namespace jelly::grade {

namespace {

using Offset = std::array<int, 3>;
using Builder = void (*)(const CubeLattice&, std::vector<Spring>&);

// e.g. "a 4×4×4 cube rotated 20° about (1,0,1) whose first particle has index 27" (whatever the
// parameters say), for the notes.
std::string lattice_words(const CubeSpec& spec, int first_index) {
  char buf[200];
  const Vec3& a = spec.rotation_axis;
  char rotation[96] = "";
  if (spec.rotation_degrees != 0.0)
    std::snprintf(rotation, sizeof rotation, " rotated %g° about (%g,%g,%g)", spec.rotation_degrees,
                  a.x(), a.y(), a.z());
  char first[96] = "";
  if (first_index != 0)
    std::snprintf(first, sizeof first,
                  " whose first particle has index %d (use cube.index(i, j, k))", first_index);
  std::snprintf(buf, sizeof buf, "a %d×%d×%d cube%s%s", spec.n, spec.n, spec.n, rotation, first);
  return buf;
}

std::string offset_name(const Offset& o) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "(%d,%d,%d)", o[0], o[1], o[2]);
  return buf;
}

// Every grid offset a spring of the jelly cube can have, canonical (first non-zero component > 0).
const std::vector<Offset>& all_offsets() {
  static const std::vector<Offset> v = {
      {1, 0, 0}, {0, 1, 0},  {0, 0, 1},                                       // structural
      {0, 1, 1}, {0, 1, -1}, {1, 0, 1},  {1, 0, -1},  {1, 1, 0}, {1, -1, 0},  // face shear
      {1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {1, -1, -1},                         // body shear
      {2, 0, 0}, {0, 2, 0},  {0, 0, 2}};                                      // bending
  return v;
}

// 64-bit FNV-1a over the sorted (min, max) pairs: equal exactly when the sets of pairs are equal.
std::string pair_set_hash(std::vector<std::pair<int, int>> pairs) {
  std::sort(pairs.begin(), pairs.end());
  std::uint64_t h = 1469598103934665603ULL;
  auto mix = [&](std::uint32_t v) {
    for (int b = 0; b < 4; ++b) {
      h ^= (v >> (8 * b)) & 0xffU;
      h *= 1099511628211ULL;
    }
  };
  for (const auto& p : pairs) {
    mix(static_cast<std::uint32_t>(p.first));
    mix(static_cast<std::uint32_t>(p.second));
  }
  char buf[24];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

// Names the first few springs of a list by the grid coordinates of their particles,
// "(0,0,0)–(1,0,0), (0,0,1)–(1,0,1) and 46 more", so that a failure says which springs.
class SpringNames {
 public:
  explicit SpringNames(const CubeLattice& cube) : cube_(cube) {}
  void add(int a, int b) {
    if (shown_ < kShown) text_ += (shown_ > 0 ? ", " : "") + coordinates(a) + "–" + coordinates(b);
    ++shown_;
  }
  std::string text() const {
    if (shown_ <= kShown) return text_;
    return text_ + " and " + std::to_string(shown_ - kShown) + " more";
  }

 private:
  static constexpr int kShown = 3;
  // "(i,j,k)" of a particle index, or "index N" when it is not one of the cube's particles.
  std::string coordinates(int index) const {
    const int n = cube_.n(), r = index - cube_.first_index();
    if (r < 0 || r >= cube_.particle_count()) return "index " + std::to_string(index);
    char buf[48];
    std::snprintf(buf, sizeof buf, "(%d,%d,%d)", r / (n * n), (r / n) % n, r % n);
    return buf;
  }
  const CubeLattice& cube_;
  std::string text_;
  int shown_ = 0;
};

void classify(const CubeLattice& cube, const std::string& what, const std::vector<Spring>& springs,
              Outputs& out) {
  const int n = cube.n(), first = cube.first_index(), count = cube.particle_count();
  std::map<Offset, int> per_offset;
  std::map<Offset, SpringNames> yours_per_offset;
  SpringNames invalid_names(cube), other_names(cube), duplicate_names(cube);
  int invalid = 0, other = 0, duplicates = 0;
  double rest_error = 0.0;
  std::set<std::pair<int, int>> seen;
  std::vector<std::pair<int, int>> pairs;
  for (const Spring& s : springs) {
    if (s.a < first || s.a >= first + count || s.b < first || s.b >= first + count || s.a == s.b) {
      ++invalid;
      invalid_names.add(s.a, s.b);
      continue;
    }
    const std::pair<int, int> key{std::min(s.a, s.b), std::max(s.a, s.b)};
    if (!seen.insert(key).second) {
      ++duplicates;
      duplicate_names.add(s.a, s.b);
    }
    pairs.push_back(key);
    const int ra = s.a - first, rb = s.b - first;
    Offset o{rb / (n * n) - ra / (n * n), (rb / n) % n - (ra / n) % n, rb % n - ra % n};
    const int lead = o[0] != 0 ? o[0] : o[1] != 0 ? o[1] : o[2];
    if (lead < 0)
      for (int& c : o) c = -c;
    if (std::find(all_offsets().begin(), all_offsets().end(), o) == all_offsets().end()) {
      ++other;
      other_names.add(s.a, s.b);
    } else {
      ++per_offset[o];
      yours_per_offset.try_emplace(o, cube).first->second.add(s.a, s.b);
    }
    const double actual =
        (cube.initial_positions().col(rb) - cube.initial_positions().col(ra)).norm();
    const double err = std::abs(s.rest_length - actual);
    rest_error = std::isfinite(err) ? std::max(rest_error, err) : err;
  }
  out.value("count", static_cast<double>(springs.size()), "number of springs appended for " + what);
  for (const Offset& o : all_offsets()) {
    const std::string name = "offset" + offset_name(o);
    out.value(name, per_offset[o],
              "springs joining particles whose grid coordinates differ by " + offset_name(o) +
                  " (either way round)");
    // The lattice's pairs at this offset that the list lacks (shown when there are too few), and
    // the list's springs at it (shown when there are too many).
    SpringNames missing(cube);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k)
          if (cube.contains(i + o[0], j + o[1], k + o[2])) {
            const int a = cube.index(i, j, k), b = cube.index(i + o[0], j + o[1], k + o[2]);
            if (!seen.count({std::min(a, b), std::max(a, b)})) missing.add(a, b);
          }
    const auto yours = yours_per_offset.find(o);
    out.detail(name, missing.text().empty() ? "" : "missing: " + missing.text(),
               yours == yours_per_offset.end() ? "" : "yours: " + yours->second.text());
  }
  out.value("other_offsets", other,
            "springs joining particles that are not neighbours at any spring offset of the cube");
  out.detail("other_offsets", "", other > 0 ? "yours: " + other_names.text() : "");
  out.value("duplicates", duplicates, "springs that join a pair of particles already joined");
  out.detail("duplicates", "", duplicates > 0 ? "built again: " + duplicate_names.text() : "");
  out.value("invalid", invalid,
            "springs with an index outside the cube's particles, or joining a particle to itself");
  out.detail("invalid", "", invalid > 0 ? "yours: " + invalid_names.text() : "");
  out.value("rest_length_error", rest_error,
            "largest |rest_length − distance between the two particles at construction| [m]");
  out.text("pair_set", pair_set_hash(pairs), "the exact set of particle pairs joined (as a hash)");
}

}  // namespace

// spring_builder: one builder (params.builder = "structural" | "shear" | "bending") on the lattice
// params.cube (n, edge, center, rotation_axis, rotation_degrees) whose first particle has index
// params.first_index (default 0).
void register_spring_cases(Registry& r) {
  GeneratorDef def;
  def.name = "spring_builder";
  def.description =
      "one spring builder on a cube lattice the framework makes; classifies what it returned";
  def.run = [](const TaskTable& tasks, const Params& params, const Json&, Outputs& out) {
    const std::string which = params.text("builder");
    Builder CubeTasks::*member = which == "structural" ? &CubeTasks::add_structural_springs
                                 : which == "shear"    ? &CubeTasks::add_shear_springs
                                 : which == "bending"  ? &CubeTasks::add_bending_springs
                                                       : nullptr;
    if (!member)
      throw std::runtime_error("params.builder: expected structural, shear or bending, got " +
                               which);
    const int first = static_cast<int>(params.integer("first_index", 0));
    const CubeSpec spec = cube_from_params(params.table("cube"));
    const CubeLattice cube(spec, first);
    std::vector<Spring> springs;
    (cube_tasks(tasks).*member)(cube, springs);
    classify(cube, lattice_words(spec, first), springs, out);
  };
  r.add(std::move(def));
}

}  // namespace jelly::grade
