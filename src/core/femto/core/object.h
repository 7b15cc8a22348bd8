#pragma once
// Base class of everything a scene file can create. Objects do not change
// while a scene renders (per-render mutable state lives in per-thread
// objects); between renders a few parameters may (setParameter).
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>
#include <string_view>

#include <femto/math/spectrum.h>

namespace femto {

class Properties;

/// The kinds of scene objects, named as in the XML tag that creates them.
/// The numeric values are part of the plugin ABI: append only.
enum class ObjectKind : int {
  Scene = 0,
  Integrator,
  Sensor,
  Film,
  Sampler,
  ReconstructionFilter,  // <rfilter>
  Shape,
  BSDF,
  Texture,
  Emitter,
  Medium,
  PhaseFunction,  // <phase>
  Volume,
};

/// XML tag spelling of a kind ("rfilter", "phase", ...).
const char* kindTag(ObjectKind kind);
/// Inverse of kindTag; nullopt for tags that do not create objects.
std::optional<ObjectKind> kindFromTag(std::string_view tag);

/// A parameter value for setParameter as a colour (1 number: grey), checked
/// finite and non-negative; errors name `owner` and `name`.
Color3f editableColor(const std::string& owner, const std::string& name, const std::vector<double>& value);
/// A parameter value for setParameter as one number in [min, max] (a whole
/// number when `whole`); errors name `owner` and `name`.
double editableNumber(const std::string& owner, const std::string& name, const std::vector<double>& value, double min,
                      double max, bool whole = false);
/// A colour as editableParameters reports it (3 numbers).
inline std::vector<double> parameterValue(const Color3f& c) { return {double(c.r), double(c.g), double(c.b)}; }

/// Parameters with their current values (1 number, or 3 for a colour), in order.
using ParameterValues = std::vector<std::pair<std::string, std::vector<double>>>;

class Object {
 public:
  virtual ~Object() = default;
  virtual ObjectKind kind() const = 0;
  /// Human-readable summary (parameters), for `femto render --verbose` and tests.
  virtual std::string toString() const;
  /// Parameters that may change after loading, between renders, with their
  /// current values (Python's Scene.parameters and Scene.set, docs/python.md
  /// "Editing a loaded scene"); none by default.
  virtual ParameterValues editableParameters() const { return {}; }
  /// Change parameter `name` to `value` (1 number, or 3 for a colour):
  /// femto::Error naming the object and what it can change otherwise. Not
  /// thread-safe: never while the scene renders.
  virtual void setParameter(const std::string& name, const std::vector<double>& value);
  /// The id="" the scene gave this object (empty when none).
  const std::string& id() const { return id_; }
  void setId(std::string id) { id_ = std::move(id); }
  /// Parameters every object of a kind takes whatever its plugin (e.g. a
  /// BSDF's scattering delay), read by the kind's base class. The plugin
  /// manager calls it right after the plugin's constructor, so plugins need
  /// not forward them.
  virtual void readCommonParameters(const Properties& props);

 private:
  std::string id_;
};

using ObjectRef = std::shared_ptr<Object>;

}  // namespace femto
