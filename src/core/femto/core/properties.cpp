#include <femto/core/properties.h>

#include <cmath>

#include <femto/core/spelling.h>

namespace femto {
namespace {

/// A bound as a person writes it: 1048576, not 1.04858e+06.
std::string bound(double v) {
  if (v == std::floor(v) && std::abs(v) < 1e15) return str(int64_t(v));
  return str(v);
}

/// " (note)" or "".
std::string parenthesised(const std::string& note) { return note.empty() ? "" : " (" + note + ")"; }

}  // namespace

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false;
  return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi);
}

std::string Range::describe() const {
  const bool hasLo = std::isfinite(lo), hasHi = std::isfinite(hi);
  if (hasLo && hasHi) return str("in ", loOpen ? "(" : "[", bound(lo), ", ", bound(hi), hiOpen ? ")" : "]");
  if (hasLo) {
    if (lo == 0.0 && loOpen) return "positive and finite";
    return str(loOpen ? "greater than " : "at least ", bound(lo), " and finite");
  }
  if (hasHi) return str(hiOpen ? "less than " : "at most ", bound(hi), " and finite");
  return "finite";
}

const char* Properties::typeName(Type t) {
  switch (t) {
    case Type::Bool: return "boolean";
    case Type::Integer: return "integer";
    case Type::Float: return "float";
    case Type::String: return "string";
    case Type::Point: return "point";
    case Type::Vector: return "vector";
    case Type::Color: return "rgb";
    case Type::Transform: return "transform";
    case Type::Object: return "object";
  }
  return "?";
}

void Properties::set(const std::string& name, Type type, Value v, SourceLocation loc) {
  auto it = values_.find(name);
  if (it != values_.end()) {
    std::string prev = it->second.loc.known() ? " (first given at " + it->second.loc.toString() + ")" : "";
    throw Error(loc.known() ? loc : location_, str("parameter \"", name, "\" is given twice", prev));
  }
  values_.emplace(name, Entry{type, std::move(v), std::move(loc)});
  order_.push_back(name);
}

void Properties::setBool(const std::string& n, bool v, SourceLocation l) { set(n, Type::Bool, v, std::move(l)); }
void Properties::setInt(const std::string& n, int64_t v, SourceLocation l) { set(n, Type::Integer, v, std::move(l)); }
void Properties::setFloat(const std::string& n, double v, SourceLocation l) { set(n, Type::Float, v, std::move(l)); }
void Properties::setString(const std::string& n, std::string v, SourceLocation l) { set(n, Type::String, std::move(v), std::move(l)); }
void Properties::setPoint(const std::string& n, const Point3f& v, SourceLocation l) { set(n, Type::Point, v, std::move(l)); }
void Properties::setVector(const std::string& n, const Vec3f& v, SourceLocation l) { set(n, Type::Vector, v, std::move(l)); }
void Properties::setColor(const std::string& n, const Color3f& v, SourceLocation l) { set(n, Type::Color, v, std::move(l)); }
void Properties::setTransform(const std::string& n, const Transform& v, SourceLocation l) { set(n, Type::Transform, v, std::move(l)); }
void Properties::setObject(const std::string& n, ObjectRef v, SourceLocation l, std::string label) {
  set(n, Type::Object, std::move(v), std::move(l));
  values_.at(n).label = std::move(label);
}

std::string Properties::describe(const std::string& name) const {
  const Entry* e = find(name);
  return e && !e->label.empty() ? e->label : str("parameter \"", name, "\"");
}

const Properties::Entry* Properties::find(const std::string& name) const {
  auto it = values_.find(name);
  return it == values_.end() ? nullptr : &it->second;
}

bool Properties::has(const std::string& name) const {
  asked_.insert(name);
  return values_.count(name) != 0;
}

std::string Properties::suggestionFor(const std::string& unusedName) const {
  // An unnamed child has no name the user could have misspelt.
  if (const Entry* e = find(unusedName); e && !e->label.empty()) return "";
  std::vector<std::string> absent;
  for (const auto& name : asked_)
    if (!values_.count(name)) absent.push_back(name);
  return didYouMean(unusedName, absent);
}

Properties::Type Properties::type(const std::string& name) const {
  const Entry* e = find(name);
  if (!e) throw Error(location_, str("parameter \"", name, "\" is not set"));
  return e->type;
}

SourceLocation Properties::location(const std::string& name) const {
  const Entry* e = find(name);
  return e && e->loc.known() ? e->loc : location_;
}

void Properties::typeError(const std::string& name, const Entry& e, const char* expected) const {
  throw Error(e.loc.known() ? e.loc : location_,
              str(describe(name), " of ", pluginName_.empty() ? std::string("object") : "\"" + pluginName_ + "\"",
                  ": expected <", expected, ">, got <", typeName(e.type), ">"));
}

const Properties::Entry& Properties::require(const std::string& name, Type expected) const {
  asked_.insert(name);
  const Entry* e = find(name);
  if (!e)
    throw Error(location_, str("\"", pluginName_, "\" is missing the required parameter \"", name, "\" (<",
                               typeName(expected), ">)"));
  e->queried = true;
  return *e;
}

void Properties::raise(const std::string& name, const std::string& message) const {
  throw Error(location(name), str(describe(name), " of \"", pluginName_, "\": ", message));
}

bool Properties::getBool(const std::string& name) const {
  const Entry& e = require(name, Type::Bool);
  if (e.type != Type::Bool) typeError(name, e, "boolean");
  return std::get<bool>(e.value);
}
bool Properties::getBool(const std::string& name, bool def) const { return has(name) ? getBool(name) : def; }

int64_t Properties::getInt(const std::string& name) const {
  const Entry& e = require(name, Type::Integer);
  if (e.type != Type::Integer) typeError(name, e, "integer");
  return std::get<int64_t>(e.value);
}
int64_t Properties::getInt(const std::string& name, int64_t def) const { return has(name) ? getInt(name) : def; }

float Properties::getFloat(const std::string& name) const {
  const Entry& e = require(name, Type::Float);
  if (e.type == Type::Integer) return float(std::get<int64_t>(e.value));
  if (e.type != Type::Float) typeError(name, e, "float");
  return float(std::get<double>(e.value));
}
float Properties::getFloat(const std::string& name, float def) const { return has(name) ? getFloat(name) : def; }

std::string Properties::getString(const std::string& name) const {
  const Entry& e = require(name, Type::String);
  if (e.type != Type::String) typeError(name, e, "string");
  return std::get<std::string>(e.value);
}
std::string Properties::getString(const std::string& name, const std::string& def) const {
  return has(name) ? getString(name) : def;
}

Point3f Properties::getPoint(const std::string& name) const {
  const Entry& e = require(name, Type::Point);
  if (e.type != Type::Point && e.type != Type::Vector) typeError(name, e, "point");
  return std::get<Vec3f>(e.value);
}
Point3f Properties::getPoint(const std::string& name, const Point3f& def) const { return has(name) ? getPoint(name) : def; }

Vec3f Properties::getVector(const std::string& name) const {
  const Entry& e = require(name, Type::Vector);
  if (e.type != Type::Point && e.type != Type::Vector) typeError(name, e, "vector");
  return std::get<Vec3f>(e.value);
}
Vec3f Properties::getVector(const std::string& name, const Vec3f& def) const { return has(name) ? getVector(name) : def; }

Color3f Properties::getColor(const std::string& name) const {
  const Entry& e = require(name, Type::Color);
  if (e.type == Type::Float) return Color3f(float(std::get<double>(e.value)));
  if (e.type == Type::Integer) return Color3f(float(std::get<int64_t>(e.value)));
  if (e.type != Type::Color) typeError(name, e, "rgb");
  return std::get<Color3f>(e.value);
}
Color3f Properties::getColor(const std::string& name, const Color3f& def) const { return has(name) ? getColor(name) : def; }

Transform Properties::getTransform(const std::string& name) const {
  const Entry& e = require(name, Type::Transform);
  if (e.type != Type::Transform) typeError(name, e, "transform");
  return std::get<Transform>(e.value);
}
Transform Properties::getTransform(const std::string& name, const Transform& def) const {
  return has(name) ? getTransform(name) : def;
}

ObjectRef Properties::getObject(const std::string& name) const {
  const Entry& e = require(name, Type::Object);
  if (e.type != Type::Object) typeError(name, e, "object");
  return std::get<ObjectRef>(e.value);
}

int64_t Properties::getInt(const std::string& name, int64_t def, int64_t lo, int64_t hi, const std::string& note) const {
  return has(name) ? getIntIn(name, lo, hi, note) : def;
}

int64_t Properties::getIntIn(const std::string& name, int64_t lo, int64_t hi, const std::string& note) const {
  int64_t v = getInt(name);
  if (v < lo || v > hi) {
    std::string range = hi == Unbounded ? str("at least ", lo) : str("in [", lo, ", ", hi, "]");
    raise(name, str("must be ", range, parenthesised(note), ", got ", v));
  }
  return v;
}

float Properties::getFloat(const std::string& name, float def, const Range& range, const std::string& note) const {
  return has(name) ? getFloatIn(name, range, note) : def;
}

float Properties::getFloatIn(const std::string& name, const Range& range, const std::string& note) const {
  float v = getFloat(name);
  checkRange(name, v, range, note);
  return v;
}

void Properties::checkRange(const std::string& name, double value, const Range& range, const std::string& note) const {
  if (!range.contains(value)) raise(name, str("must be ", range.describe(), parenthesised(note), ", got ", value));
}

size_t Properties::choiceIndex(const std::string& name,
                               const std::vector<std::pair<std::string, std::string>>& choices) const {
  const std::string value = getString(name);
  std::vector<std::string> names;
  for (size_t i = 0; i < choices.size(); ++i) {
    if (choices[i].first == value) return i;
    names.push_back(choices[i].first);
  }
  std::string expected;
  for (size_t i = 0; i < choices.size(); ++i) {
    if (i > 0) expected += i + 1 == choices.size() ? " or " : ", ";
    expected += str("\"", choices[i].first, "\"", parenthesised(choices[i].second));
  }
  raise(name, str("expected ", expected, ", got \"", value, "\"", didYouMean(value, names)));
}

std::vector<ObjectRef> Properties::objectsOfKind(ObjectKind kind, const std::string& except) const {
  std::vector<ObjectRef> out;
  for (const auto& name : order_) {
    if (!except.empty() && name == except) continue;
    const Entry& e = values_.at(name);
    if (e.type != Type::Object) continue;
    const ObjectRef& obj = std::get<ObjectRef>(e.value);
    if (obj && obj->kind() == kind) {
      e.queried = true;
      out.push_back(obj);
    }
  }
  return out;
}

ObjectRef Properties::objectOfKind(ObjectKind kind, const std::string& except) const {
  auto all = objectsOfKind(kind, except);
  if (all.size() > 1)
    throw Error(location_, str("\"", pluginName_, "\" takes at most one nested <", kindTag(kind), ">, got ", all.size()));
  return all.empty() ? nullptr : all.front();
}

void Properties::markQueried(const std::string& name) const {
  if (const Entry* e = find(name)) e->queried = true;
}

bool Properties::wasQueried(const std::string& name) const {
  const Entry* e = find(name);
  return e && e->queried;
}

std::vector<std::string> Properties::unqueried() const {
  std::vector<std::string> out;
  for (const auto& name : order_)
    if (!values_.at(name).queried) out.push_back(name);
  return out;
}

}  // namespace femto
