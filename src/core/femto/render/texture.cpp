#include <femto/render/texture.h>

namespace femto {

std::string ConstantTexture::toString() const { return str("ConstantTexture[value=", value_, "]"); }

UvMapping::UvMapping(const Properties& props) {
  const char* legacy[] = {"uscale", "vscale", "uoffset", "voffset"};
  bool hasLegacy = false;
  for (const char* name : legacy) hasLegacy |= props.has(name);
  if (props.has("to_uv")) {
    if (hasLegacy)
      props.raise("to_uv", "give either \"to_uv\" or uscale/vscale/uoffset/voffset, not both");
    toUv_ = props.getTransform("to_uv");
    return;
  }
  if (hasLegacy) {
    Vec3f scale(props.getFloat("uscale", 1.0f), props.getFloat("vscale", 1.0f), 1.0f);
    Vec3f offset(props.getFloat("uoffset", 0.0f), props.getFloat("voffset", 0.0f), 0.0f);
    toUv_ = Transform::translate(offset) * Transform::scale(scale);
  }
}

Point2f UvMapping::operator()(const Point2f& uv) const {
  Point3f p = toUv_.point(Point3f(uv.x, uv.y, 0.0f));
  return {p.x, p.y};
}

std::shared_ptr<Texture> textureOrColor(const Properties& props, const std::string& name, const Color3f& def) {
  if (!props.has(name)) return std::make_shared<ConstantTexture>(def);
  if (props.type(name) == Properties::Type::Object) {
    auto texture = std::dynamic_pointer_cast<Texture>(props.getObject(name));
    if (!texture) props.raise(name, "expected a <texture> or a colour value");
    return texture;
  }
  return std::make_shared<ConstantTexture>(props.getColor(name));
}

}  // namespace femto
