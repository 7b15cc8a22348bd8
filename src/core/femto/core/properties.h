#pragma once
// Typed parameters of one scene object, as the XML gave them. Each value keeps
// its type, its file:line and whether the plugin read it, so the loader (not
// each plugin) can report parameters nobody used, and wrong types are reported
// in XML words ("expected <float>, got <rgb>").
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include <femto/base/error.h>
#include <femto/core/object.h>
#include <femto/math/transform.h>
#include <femto/math/vector.h>
#include <femto/math/spectrum.h>

namespace femto {

/// The values a float parameter may take: an interval whose ends are each
/// open or closed, possibly unbounded. Non-finite values (NaN, inf) are never
/// in range. Reads like the parameter table: Range::positive(),
/// Range::closed(0, 1), Range::leftOpen(0, 1) for (0, 1].
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool loOpen = false, hiOpen = false;

  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }      // [lo, hi]
  static Range open(double lo, double hi) { return {lo, hi, true, true}; }          // (lo, hi)
  static Range leftOpen(double lo, double hi) { return {lo, hi, true, false}; }     // (lo, hi]
  static Range rightOpen(double lo, double hi) { return {lo, hi, false, true}; }    // [lo, hi)
  static Range atLeast(double lo) { return {lo, std::numeric_limits<double>::infinity(), false, true}; }  // >= lo
  static Range greaterThan(double lo) { return {lo, std::numeric_limits<double>::infinity(), true, true}; }  // > lo
  static Range positive() { return greaterThan(0.0); }     // > 0
  static Range nonNegative() { return atLeast(0.0); }      // >= 0
  static Range finite() { return {}; }                     // any finite value

  bool contains(double v) const;
  /// What the message says: "in (0, 1]", "positive", ">= 0", "finite".
  std::string describe() const;
};

/// One value of a string-valued enumeration: its spelling in the scene, the
/// C++ value and, optionally, what it means (shown when the value is unknown).
template <typename E>
struct EnumValue {
  const char* name;
  E value;
  const char* meaning = nullptr;
};

class Properties {
 public:
  /// The XML element a value came from: its tag decides the type's name in messages.
  enum class Type { Bool, Integer, Float, String, Point, Vector, Color, Transform, Object };
  static const char* typeName(Type t);  // "boolean", "integer", "float", "string", "point", "vector", "rgb", "transform", "object"

  Properties() = default;
  explicit Properties(std::string pluginName) : pluginName_(std::move(pluginName)) {}

  /// The plugin type="" this object is created from (e.g. "diffuse").
  const std::string& pluginName() const { return pluginName_; }
  void setPluginName(std::string n) { pluginName_ = std::move(n); }
  /// id="" of the object (may be empty).
  const std::string& id() const { return id_; }
  void setId(std::string id) { id_ = std::move(id); }
  /// Where the object itself was declared.
  const SourceLocation& location() const { return location_; }
  void setLocation(SourceLocation loc) { location_ = std::move(loc); }

  /// Is the parameter present? Also records `name` as asked for (see askedNames).
  bool has(const std::string& name) const;
  /// Type of a present parameter; throws if absent.
  Type type(const std::string& name) const;
  /// File:line of a parameter (the object's own location when absent).
  SourceLocation location(const std::string& name) const;
  /// Names in insertion order.
  std::vector<std::string> names() const { return order_; }

  // Setters. A second value under the same name is an error naming both lines.
  void setBool(const std::string& name, bool v, SourceLocation loc = {});
  void setInt(const std::string& name, int64_t v, SourceLocation loc = {});
  void setFloat(const std::string& name, double v, SourceLocation loc = {});
  void setString(const std::string& name, std::string v, SourceLocation loc = {});
  void setPoint(const std::string& name, const Point3f& v, SourceLocation loc = {});
  void setVector(const std::string& name, const Vec3f& v, SourceLocation loc = {});
  void setColor(const std::string& name, const Color3f& v, SourceLocation loc = {});
  void setTransform(const std::string& name, const Transform& v, SourceLocation loc = {});
  /// Nested objects and references. Unnamed children get a generated name
  /// ("_arg_0", ...) from the loader, which never reaches a message: the
  /// loader gives them a `label` saying what the user wrote (see describe).
  void setObject(const std::string& name, ObjectRef v, SourceLocation loc = {}, std::string label = {});
  /// How messages name a parameter: its label when it has one (e.g. `nested
  /// <medium type="homogeneous" id="fog"> (line 4)`), else `parameter "name"`.
  std::string describe(const std::string& name) const;

  // Getters mark the parameter as read. The forms without a default throw
  // "missing parameter" errors naming the object's file:line. Wrong types throw
  // errors naming the parameter's file:line. Integers are accepted where floats
  // are expected; a float (grey) where a colour is expected.
  bool getBool(const std::string& name) const;
  bool getBool(const std::string& name, bool def) const;
  int64_t getInt(const std::string& name) const;
  int64_t getInt(const std::string& name, int64_t def) const;
  float getFloat(const std::string& name) const;
  float getFloat(const std::string& name, float def) const;
  std::string getString(const std::string& name) const;
  std::string getString(const std::string& name, const std::string& def) const;
  Point3f getPoint(const std::string& name) const;
  Point3f getPoint(const std::string& name, const Point3f& def) const;
  Vec3f getVector(const std::string& name) const;
  Vec3f getVector(const std::string& name, const Vec3f& def) const;
  Color3f getColor(const std::string& name) const;
  Color3f getColor(const std::string& name, const Color3f& def) const;
  Transform getTransform(const std::string& name) const;
  Transform getTransform(const std::string& name, const Transform& def) const;
  ObjectRef getObject(const std::string& name) const;

  // Checked getters: one call per row of a plugin's parameter table. Out of
  // range values raise (see raise) "must be in [lo, hi], got v" at the
  // parameter's file:line; `note` (e.g. "-1: no limit", "bins") is added in
  // parentheses after the range. The default is returned unchecked.
  /// `hi` of an integer range without an upper bound.
  static constexpr int64_t Unbounded = std::numeric_limits<int64_t>::max();
  /// An integer in the closed range [lo, hi] (hi = Unbounded: "must be at least lo").
  int64_t getInt(const std::string& name, int64_t def, int64_t lo, int64_t hi, const std::string& note = "") const;
  /// A required integer in [lo, hi].
  int64_t getIntIn(const std::string& name, int64_t lo, int64_t hi, const std::string& note = "") const;
  /// A finite float in `range`.
  float getFloat(const std::string& name, float def, const Range& range, const std::string& note = "") const;
  /// A required finite float in `range`.
  float getFloatIn(const std::string& name, const Range& range, const std::string& note = "") const;
  /// Check a value derived from parameter `name` (e.g. a length given in
  /// seconds, converted) against `range`, with the same message.
  void checkRange(const std::string& name, double value, const Range& range, const std::string& note = "") const;
  /// A string from a fixed set, as the matching enumerator; absent: `def`.
  /// Unknown values raise `expected "a" (meaning), "b" or "c", got "x"`
  /// with a "did you mean" hint.
  template <typename E>
  E getEnum(const std::string& name, E def, std::initializer_list<EnumValue<E>> values) const {
    if (!has(name)) return def;
    std::vector<std::pair<std::string, std::string>> choices;
    for (const auto& v : values) choices.emplace_back(v.name, v.meaning ? v.meaning : "");
    return (values.begin() + choiceIndex(name, choices))->value;
  }

  /// All nested objects (named or not) of the given kind, in document order,
  /// marking them as read; `except` names one to leave out (a nested object
  /// of that kind with a role of its own, e.g. a film's "tfilter").
  std::vector<ObjectRef> objectsOfKind(ObjectKind kind, const std::string& except = "") const;
  /// The single nested object of a kind, or nullptr; more than one is an error.
  ObjectRef objectOfKind(ObjectKind kind, const std::string& except = "") const;
  /// Nested object (of `kind`) under `name` if present, else the single
  /// unnamed-or-named child of that kind; nullptr when none.
  template <typename T>
  std::shared_ptr<T> object(ObjectKind kind) const {
    return std::dynamic_pointer_cast<T>(objectOfKind(kind));
  }

  /// Helpers for validation with file:line: throw "bad value" errors.
  [[noreturn]] void raise(const std::string& name, const std::string& message) const;

  void markQueried(const std::string& name) const;
  bool wasQueried(const std::string& name) const;
  /// Parameters nobody read, in document order.
  std::vector<std::string> unqueried() const;
  /// Every name a plugin asked for (get*, has), present or not: the
  /// vocabulary of the plugin, used for "did you mean" hints.
  std::vector<std::string> askedNames() const { return {asked_.begin(), asked_.end()}; }
  /// " (did you mean "x"?)" for an unused parameter, from the asked-for names that are absent; or "".
  std::string suggestionFor(const std::string& unusedName) const;

 private:
  using Value = std::variant<bool, int64_t, double, std::string, Vec3f, Color3f, Transform, ObjectRef>;
  struct Entry {
    Type type;
    Value value;
    SourceLocation loc;
    std::string label;  // what messages call an unnamed child; empty for named parameters
    mutable bool queried = false;
  };
  void set(const std::string& name, Type type, Value v, SourceLocation loc);
  const Entry* find(const std::string& name) const;
  const Entry& require(const std::string& name, Type expected) const;
  [[noreturn]] void typeError(const std::string& name, const Entry& e, const char* expected) const;
  /// Index of the (present) string parameter's value among the choices' names; raises when unknown.
  size_t choiceIndex(const std::string& name, const std::vector<std::pair<std::string, std::string>>& choices) const;

  std::string pluginName_, id_;
  SourceLocation location_;
  std::map<std::string, Entry> values_;
  std::vector<std::string> order_;
  mutable std::set<std::string> asked_;
};

}  // namespace femto
