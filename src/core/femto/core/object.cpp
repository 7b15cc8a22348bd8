#include <femto/core/object.h>

#include <array>

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

std::string Object::toString() const { return std::string(kindTag(kind())) + (id_.empty() ? "" : " id=\"" + id_ + "\""); }

void Object::readCommonParameters(const Properties&) {}

}  // namespace femto
