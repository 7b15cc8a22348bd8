#include <femto/core/object.h>

#include <array>
#include <cmath>
#include <limits>

#include <femto/base/error.h>

namespace femto {
namespace {
constexpr std::array<const char*, 13> Tags = {"scene", "integrator", "sensor", "film", "sampler", "rfilter", "shape",
                                               "bsdf",  "texture",    "emitter", "medium", "phase", "volume"};
}

const char* kindTag(ObjectKind kind) { return Tags.at(size_t(kind)); }

std::optional<ObjectKind> kindFromTag(std::string_view tag) {
  for (size_t i = 0; i < Tags.size(); ++i)
    if (tag == Tags[i]) return ObjectKind(i);
  return std::nullopt;
}

void Object::setParameter(const std::string& name, const std::vector<double>&) {
  std::string editable;
  for (const auto& [p, value] : editableParameters()) editable += (editable.empty() ? "" : ", ") + p;
  throw Error(str(toString(), ": \"", name, "\" cannot change after loading",
                  editable.empty() ? std::string(" (nothing of it can)") : " (it can change: " + editable + ")"));
}

double editableNumber(const std::string& owner, const std::string& name, const std::vector<double>& value, double min,
                      double max, bool whole) {
  if (value.size() != 1 || !(value[0] >= min && value[0] <= max) || (whole && value[0] != std::floor(value[0])))
    throw Error(str(owner, ": \"", name, "\" takes one ", whole ? "whole number" : "number", " from ", min, " to ", max,
                    value.size() == 1 ? str(", got ", value[0]) : str(", got ", value.size(), " numbers")));
  return value[0];
}

Color3f editableColor(const std::string& owner, const std::string& name, const std::vector<double>& value) {
  if (value.size() != 1 && value.size() != 3)
    throw Error(str(owner, ": \"", name, "\" takes 1 or 3 numbers, got ", value.size()));
  Color3f c(float(value[0]), float(value[value.size() == 3 ? 1 : 0]), float(value[value.size() == 3 ? 2 : 0]));
  if (!c.isValid()) throw Error(str(owner, ": \"", name, "\" must be finite and non-negative"));
  return c;
}

std::string Object::toString() const { return std::string(kindTag(kind())) + (id_.empty() ? "" : " id=\"" + id_ + "\""); }

void Object::readCommonParameters(const Properties&) {}

}  // namespace femto
