// A2.T1–T3 cases: the student's grid builders on cloths the framework makes (ClothGrid). Nothing
// here knows how to build springs: the cases classify what a builder returned (by grid offset,
// by the type each offset belongs to, duplicates, indices, rest lengths) and the orchestrator
// compares that with the reference's classification. A failure names the first missing or extra
// springs by grid coordinates, "(3,4)–(4,5)", and springs of another type by their type (shear
// and bending swapped).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

#include "cases.hpp"

namespace jelly::grade {

namespace {

using Offset = std::array<int, 2>;
using Builder = void (*)(const ClothGrid&, std::vector<Spring>&);

struct OffsetType {
  Offset offset;
  const char* type;  // the builder it belongs to (cloth contract §2)
};

// Every grid offset a cloth spring can have, canonical (first non-zero component > 0), with its
// type.
const std::vector<OffsetType>& all_offsets() {
  static const std::vector<OffsetType> v = {{{1, 0}, "structural"}, {{0, 1}, "structural"},
                                            {{1, 1}, "shear"},      {{1, -1}, "shear"},
                                            {{2, 0}, "bending"},    {{0, 2}, "bending"}};
  return v;
}

std::string offset_name(const Offset& o) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "(%d,%d)", o[0], o[1]);
  return buf;
}

// e.g. "a 5×5 cloth rotated 30° about (1,1,0) whose first particle has index 8".
std::string cloth_words(const ClothSpec& spec, int first_index) {
  char rotation[96] = "";
  const Vec3& a = spec.rotation_axis;
  if (spec.rotation_degrees != 0.0)
    std::snprintf(rotation, sizeof rotation, " rotated %g° about (%g,%g,%g)", spec.rotation_degrees,
                  a.x(), a.y(), a.z());
  char first[96] = "";
  if (first_index != 0)
    std::snprintf(first, sizeof first, " whose first particle has index %d (use cloth.index(i, k))",
                  first_index);
  char buf[240];
  std::snprintf(buf, sizeof buf, "a %d×%d cloth%s%s", spec.n, spec.n, rotation, first);
  return buf;
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
// "(3,4)–(4,5), (3,5)–(4,6) and 46 more".
class SpringNames {
 public:
  explicit SpringNames(const ClothGrid& cloth) : cloth_(&cloth) {}
  void add(int a, int b) {
    if (shown_ < kShown) text_ += (shown_ > 0 ? ", " : "") + coordinates(a) + "–" + coordinates(b);
    ++shown_;
  }
  int count() const { return shown_; }
  std::string text() const {
    if (shown_ <= kShown) return text_;
    return text_ + " and " + std::to_string(shown_ - kShown) + " more";
  }

 private:
  static constexpr int kShown = 3;
  // "(i,k)" of a particle index, or "index N" when it is not one of the cloth's particles.
  std::string coordinates(int index) const {
    const int n = cloth_->n(), r = index - cloth_->first_index();
    if (r < 0 || r >= cloth_->particle_count()) return "index " + std::to_string(index);
    return grid_name(r / n, r % n);
  }
  const ClothGrid* cloth_;
  std::string text_;
  int shown_ = 0;
};

void classify(const ClothGrid& cloth, const std::string& builder, const std::string& what,
              const std::vector<Spring>& springs, Outputs& out) {
  const int n = cloth.n(), first = cloth.first_index(), count = cloth.particle_count();
  std::map<Offset, int> per_offset;
  std::map<Offset, SpringNames> yours_per_offset;
  SpringNames invalid_names(cloth), other_names(cloth), duplicate_names(cloth),
      other_type_names(cloth);
  int invalid = 0, other = 0, duplicates = 0;
  std::map<std::string, int> per_type;
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
    Offset o{rb / n - ra / n, rb % n - ra % n};
    if (o[0] < 0 || (o[0] == 0 && o[1] < 0)) o = {-o[0], -o[1]};
    const auto known = std::find_if(all_offsets().begin(), all_offsets().end(),
                                    [&](const OffsetType& t) { return t.offset == o; });
    if (known == all_offsets().end()) {
      ++other;
      other_names.add(s.a, s.b);
    } else {
      ++per_offset[o];
      ++per_type[known->type];
      yours_per_offset.try_emplace(o, cloth).first->second.add(s.a, s.b);
      if (builder != known->type) other_type_names.add(s.a, s.b);
    }
    const double actual =
        (cloth.initial_positions().col(rb) - cloth.initial_positions().col(ra)).norm();
    const double err = std::abs(s.rest_length - actual);
    rest_error = std::isfinite(err) ? std::max(rest_error, err) : err;
  }
  out.value("count", static_cast<double>(springs.size()), "number of springs appended for " + what);
  // Springs of another type than this builder's: e.g. the shear builder making bending springs
  // (the course's students swapped the two).
  std::string types_seen;
  for (const auto& [type, c] : per_type)
    if (type != builder)
      types_seen += (types_seen.empty() ? "" : ", ") + std::to_string(c) + " " + type;
  out.value("other_type", other_type_names.count(),
            "springs at an offset of another type than " + builder +
                " (structural (1,0) (0,1); shear (1,1) (1,−1); bending (2,0) (0,2))");
  out.detail("other_type", "",
             other_type_names.count() > 0
                 ? "yours: " + types_seen + " spring(s), " + other_type_names.text() +
                       " — are the types swapped?"
                 : "");
  for (const OffsetType& t : all_offsets()) {
    const Offset& o = t.offset;
    const std::string name = "offset" + offset_name(o);
    out.value(name, per_offset[o],
              "springs joining particles whose grid coordinates (i,k) differ by " + offset_name(o) +
                  " (either way round), " + (builder == t.type ? "a " : "NOT a ") + builder +
                  " offset: " + t.type + " springs are at it");
    // The grid's pairs at this offset that the list lacks (shown when there are too few), and
    // the list's springs at it (shown when there are too many).
    SpringNames missing(cloth);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < n; ++k)
        if (cloth.contains(i + o[0], k + o[1])) {
          const int a = cloth.index(i, k), b = cloth.index(i + o[0], k + o[1]);
          if (!seen.count({std::min(a, b), std::max(a, b)})) missing.add(a, b);
        }
    const auto yours = yours_per_offset.find(o);
    out.detail(name, missing.text().empty() ? "" : missing.text() + " missing",
               yours == yours_per_offset.end() ? "" : "yours: " + yours->second.text());
  }
  out.value("other_offsets", other,
            "springs joining particles that are not neighbours at any spring offset of the cloth");
  out.detail("other_offsets", "", other > 0 ? "yours: " + other_names.text() : "");
  out.value("duplicates", duplicates, "springs that join a pair of particles already joined");
  out.detail("duplicates", "", duplicates > 0 ? "built again: " + duplicate_names.text() : "");
  out.value("invalid", invalid,
            "springs with an index outside the cloth's particles, or joining a particle to itself");
  out.detail("invalid", "", invalid > 0 ? "yours: " + invalid_names.text() : "");
  out.value("rest_length_error", rest_error,
            "largest |rest_length − distance between the two particles at construction| [m]");
  out.text("pair_set", pair_set_hash(pairs), "the exact set of particle pairs joined (as a hash)");
}

}  // namespace

std::string grid_name(int i, int k) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "(%d,%d)", i, k);
  return buf;
}

ClothSpec cloth_from_params(const Params& cloth) {
  ClothSpec spec;
  spec.n = static_cast<int>(cloth.integer("n"));
  if (spec.n < 2) throw std::runtime_error("params.cloth.n: expected at least 2");
  spec.size = cloth.number("size", spec.size);
  spec.center = cloth.vec("center", Vec3::Zero());
  spec.rotation_axis = cloth.vec("rotation_axis", Vec3(1.0, 0.0, 0.0));
  spec.rotation_degrees = cloth.number("rotation_degrees", 0.0);
  spec.pin_sets.clear();
  if (cloth.has("pins"))
    for (const Json& p : cloth.json().at("pins"))
      spec.pins.push_back({p.at(0).get<int>(), p.at(1).get<int>()});
  return spec;
}

// grid_spring_builder: one builder (params.builder = "structural" | "shear" | "bending") on the
// cloth params.cloth (n, size, center, rotation_axis, rotation_degrees) whose first particle has
// index params.first_index (default 0).
void register_grid_spring_cases(Registry& r) {
  GeneratorDef def;
  def.name = "grid_spring_builder";
  def.description =
      "one spring builder on a cloth grid the framework makes; classifies what it returned";
  def.run = [](const TaskTable& tasks, const Params& params, const Json&, Outputs& out) {
    const std::string which = params.text("builder");
    Builder ClothTasks::*member = which == "structural" ? &ClothTasks::add_grid_structural_springs
                                  : which == "shear"    ? &ClothTasks::add_grid_shear_springs
                                  : which == "bending"  ? &ClothTasks::add_grid_bending_springs
                                                        : nullptr;
    if (!member)
      throw std::runtime_error("params.builder: expected structural, shear or bending, got " +
                               which);
    const int first = static_cast<int>(params.integer("first_index", 0));
    const ClothSpec spec = cloth_from_params(params.table("cloth"));
    const ClothGrid cloth(spec, first);
    std::vector<Spring> springs;
    (cloth_tasks(tasks).*member)(cloth, springs);
    classify(cloth, which, cloth_words(spec, first), springs, out);
  };
  r.add(std::move(def));
}

}  // namespace jelly::grade
