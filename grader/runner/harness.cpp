#include "harness.hpp"

#include <cmath>
#include <stdexcept>

namespace jelly::grade {

namespace {
Json number(double v) {
  // JSON has no NaN or infinity: they are written as null and the orchestrator reports them.
  return std::isfinite(v) ? Json(v) : Json(nullptr);
}
Json entry(Json value, const std::string& note) {
  Json e = Json::object();
  e["value"] = std::move(value);
  if (!note.empty()) e["note"] = note;
  return e;
}
}  // namespace

void Outputs::value(const std::string& name, double v, const std::string& note) {
  out_[name] = entry(number(v), note);
}

void Outputs::vec(const std::string& name, const Vec3& v, const std::string& note) {
  values(name, {v.x(), v.y(), v.z()}, note);
}

void Outputs::values(const std::string& name, const std::vector<double>& v, const std::string& note) {
  Json a = Json::array();
  for (double d : v) a.push_back(number(d));
  out_[name] = entry(std::move(a), note);
}

void Outputs::array(const std::string& name, const Vec3Array& a, const std::string& note) {
  std::vector<double> v(a.data(), a.data() + a.size());
  values(name, v, note);
}

void Outputs::text(const std::string& name, const std::string& v, const std::string& note) {
  out_[name] = entry(Json(v), note);
}

void Registry::add(CaseDef def) {
  if (find(def.id)) throw std::logic_error("duplicate grading case id " + def.id);
  cases_.push_back(std::move(def));
}

const CaseDef* Registry::find(const std::string& id) const {
  for (const CaseDef& c : cases_)
    if (c.id == id) return &c;
  return nullptr;
}

Json springs_to_json(const std::vector<Spring>& springs) {
  Json a = Json::array();
  for (const Spring& s : springs) a.push_back(Json::array({s.a, s.b, s.rest_length}));
  return a;
}

std::vector<Spring> springs_from_json(const Json& j) {
  std::vector<Spring> out;
  out.reserve(j.size());
  for (const Json& s : j) out.push_back(Spring{s.at(0).get<int>(), s.at(1).get<int>(), s.at(2).get<double>()});
  return out;
}

CubeSpec small_cube_spec() {
  CubeSpec s;
  s.n = 3;
  s.edge = 2.0;
  s.center = Vec3(0.0, 5.0, 0.0);
  s.rotation_axis = Vec3(1.0, 0.0, 1.0);
  s.rotation_degrees = 20.0;
  return s;
}

void prepare_small_cube_springs(const TaskTable& reference, Json& input) {
  const CubeLattice cube(small_cube_spec(), 0);
  std::vector<Spring> structural, shear, bending;
  reference.add_structural_springs(cube, structural);
  reference.add_shear_springs(cube, shear);
  reference.add_bending_springs(cube, bending);
  input["springs"] = {{"structural", springs_to_json(structural)},
                      {"shear", springs_to_json(shear)},
                      {"bending", springs_to_json(bending)}};
}

void add_small_cube(World& world, const Json& input, double ks, double kd) {
  const int cube = world.add_cube(small_cube_spec());
  const double spacing = world.cubes().at(static_cast<std::size_t>(cube)).spacing();
  const std::pair<const char*, SpringType> types[] = {{"structural", SpringType::Structural},
                                                      {"shear", SpringType::Shear},
                                                      {"bending", SpringType::Bending}};
  for (const auto& [key, type] : types) {
    SpringGroup g;
    g.type = type;
    g.ks = ks;
    g.kd = kd;
    g.degenerate_length = 1e-12 * spacing;
    g.springs = springs_from_json(input.at("springs").at(key));
    world.add_spring_group(std::move(g));
  }
}

double Sequence::next() {
  // PCG-style LCG step; the top 53 bits give a double in [0, 1).
  state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
  const double unit = static_cast<double>(state_ >> 11) * (1.0 / 9007199254740992.0);
  return 2.0 * unit - 1.0;
}

}  // namespace jelly::grade
