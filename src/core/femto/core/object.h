#pragma once
// Base class of everything a scene file can create. Objects are immutable
// once constructed; per-render mutable state lives in per-thread objects.
#include <memory>
#include <optional>
#include <string>
#include <string_view>

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

class Object {
 public:
  virtual ~Object() = default;
  virtual ObjectKind kind() const = 0;
  /// Human-readable summary (parameters), for `femto render --verbose` and tests.
  virtual std::string toString() const;
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
