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

void Outputs::values(const std::string& name, const std::vector<double>& v,
                     const std::string& note) {
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

void Outputs::detail(const std::string& name, const std::string& low, const std::string& high) {
  Json& e = out_.at(name);
  if (!low.empty()) e["detail_low"] = low;
  if (!high.empty()) e["detail_high"] = high;
}

void Registry::add(GeneratorDef def) {
  if (find(def.name)) throw std::logic_error("duplicate case generator " + def.name);
  generators_.push_back(std::move(def));
}

const GeneratorDef* Registry::find(const std::string& name) const {
  for (const GeneratorDef& g : generators_)
    if (g.name == name) return &g;
  return nullptr;
}

const Json& Params::at(const std::string& key) const {
  if (!has(key))
    throw std::runtime_error(path_ + "." + key +
                             " is missing (see the case in the assignment's grader/cases/)");
  return j_.at(key);
}

void Params::wrong(const std::string& key, const char* expected) const {
  throw std::runtime_error(path_ + "." + key + ": expected " + expected + ", got " +
                           j_.at(key).dump());
}

double Params::number(const std::string& key) const {
  const Json& v = at(key);
  if (!v.is_number()) wrong(key, "a number");
  return v.get<double>();
}

long Params::integer(const std::string& key) const {
  const Json& v = at(key);
  if (!v.is_number_integer()) wrong(key, "an integer");
  return v.get<long>();
}

std::string Params::text(const std::string& key) const {
  const Json& v = at(key);
  if (!v.is_string()) wrong(key, "a string");
  return v.get<std::string>();
}

Vec3 Params::vec(const std::string& key) const {
  const Json& v = at(key);
  if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
    wrong(key, "an array of 3 numbers");
  return Vec3(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
}

std::vector<double> Params::numbers(const std::string& key) const {
  const Json& v = at(key);
  if (!v.is_array()) wrong(key, "an array of numbers");
  std::vector<double> out;
  for (const Json& e : v) {
    if (!e.is_number()) wrong(key, "an array of numbers");
    out.push_back(e.get<double>());
  }
  return out;
}

Params Params::table(const std::string& key) const {
  const Json& v = at(key);
  if (!v.is_object()) wrong(key, "a table");
  return Params(v, path_ + "." + key);
}

std::vector<Params> Params::list(const std::string& key) const {
  const Json& v = at(key);
  if (!v.is_array()) wrong(key, "an array of tables");
  std::vector<Params> out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!v[i].is_object()) wrong(key, "an array of tables");
    out.emplace_back(v[i], path_ + "." + key + "[" + std::to_string(i) + "]");
  }
  return out;
}

Json springs_to_json(const std::vector<Spring>& springs) {
  Json a = Json::array();
  for (const Spring& s : springs) a.push_back(Json::array({s.a, s.b, s.rest_length}));
  return a;
}

std::vector<Spring> springs_from_json(const Json& j) {
  std::vector<Spring> out;
  out.reserve(j.size());
  for (const Json& s : j)
    out.push_back(Spring{s.at(0).get<int>(), s.at(1).get<int>(), s.at(2).get<double>()});
  return out;
}

double Sequence::next() {
  // PCG-style LCG step; the top 53 bits give a double in [0, 1).
  state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
  const double unit = static_cast<double>(state_ >> 11) * (1.0 / 9007199254740992.0);
  return 2.0 * unit - 1.0;
}

Vec3 Sequence::next3() {
  const double z = next();
  const double y = next();
  const double x = next();
  return Vec3(x, y, z);
}

}  // namespace jelly::grade
