#include <femto/render/texture.h>

namespace femto {

std::string ConstantTexture::toString() const { return str("ConstantTexture[value=", value_, "]"); }

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
