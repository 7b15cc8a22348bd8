#include "value_properties.h"

#include <array>

#include "parse_values.h"
#include "scene_error.h"

namespace femto::xml {
namespace {

/// value="x, y, z", or x/y/z attributes where missing ones are `missing`.
Vec3f vectorAttributes(const XmlNode& node, float missing) {
  if (const std::string* value = node.attribute("value")) return parseVector3(*value);
  Vec3f v(missing);
  const char* axes[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i)
    if (const std::string* a = node.attribute(axes[i])) v[i] = float(parseFloat(*a));
  return v;
}

Transform transformOp(const XmlNode& op) {
  if (op.tag == "translate") return Transform::translate(vectorAttributes(op, 0.0f));
  if (op.tag == "scale") {
    const std::string* value = op.attribute("value");
    if (value && parseNumberList(*value).size() == 1) return Transform::scale(Vec3f(float(parseFloat(*value))));
    return Transform::scale(vectorAttributes(op, 1.0f));
  }
  if (op.tag == "rotate") {
    Vec3f axis = vectorAttributes(op, 0.0f);
    if (axis == Vec3f(0.0f)) throw Error("<rotate> needs a non-zero axis (x, y, z or value)");
    return Transform::rotate(axis, float(parseFloat(requireAttribute(op, "angle"))));
  }
  if (op.tag == "matrix") {
    auto v = parseNumberList(requireAttribute(op, "value"));
    if (v.size() != 16) throw Error(str("<matrix> needs 16 numbers, got ", v.size()));
    std::array<float, 16> values{};
    for (size_t i = 0; i < 16; ++i) values[i] = float(v[i]);
    return Transform(Matrix4f::fromRows(values));
  }
  if (op.tag == "lookat" || op.tag == "lookAt") {
    Point3f origin = parseVector3(requireAttribute(op, "origin"));
    Point3f target = parseVector3(requireAttribute(op, "target"));
    Vec3f up = op.attribute("up") ? parseVector3(*op.attribute("up")) : Vec3f(0, 1, 0);
    Vec3f dir = target - origin;
    if (dot(dir, dir) == 0.0f) throw Error("<lookat> origin and target coincide");
    if (squaredLength(cross(dir, up)) == 0.0f) throw Error("<lookat> up is parallel to the viewing direction");
    return Transform::lookAt(origin, target, up);
  }
  throw Error(str("unsupported tag <", op.tag, "> inside <transform> (expected translate, rotate, scale, matrix or lookat)"));
}

}  // namespace

bool isValueTag(const std::string& tag) {
  static const char* tags[] = {"float", "integer", "boolean", "string", "point",    "vector",
                               "rgb",   "srgb",    "color",   "spectrum", "transform"};
  for (const char* t : tags)
    if (tag == t) return true;
  return false;
}

Transform parseTransform(const XmlNode& node) {
  Transform t;
  for (const auto& op : node.children) {
    try {
      t = transformOp(op) * t;
    } catch (const Error& e) {
      if (isEchoed(e)) throw;
      throw sceneError(op, e.what());
    }
  }
  return t;
}

void addValueProperty(Properties& props, const XmlNode& node, const FileResolver& resolver) {
  const std::string& name = requireAttribute(node, "name");
  const SourceLocation& loc = node.location;
  try {
    if (node.tag == "transform") {
      props.setTransform(name, parseTransform(node), loc);
      return;
    }
    if (node.tag == "point" || node.tag == "vector") {
      Vec3f v = vectorAttributes(node, 0.0f);
      node.tag == "point" ? props.setPoint(name, v, loc) : props.setVector(name, v, loc);
      return;
    }
    const std::string& value = requireAttribute(node, "value");
    if (node.tag == "float") props.setFloat(name, parseFloat(value), loc);
    else if (node.tag == "integer") props.setInt(name, parseInteger(value), loc);
    else if (node.tag == "boolean") props.setBool(name, parseBoolean(value), loc);
    else if (node.tag == "rgb" || node.tag == "color") props.setColor(name, parseRgb(value), loc);
    else if (node.tag == "srgb") props.setColor(name, parseSrgb(value), loc);
    else if (node.tag == "spectrum") props.setColor(name, parseSpectrum(value), loc);
    else if (node.tag == "string" && name == "filename") {
      auto file = resolver.resolve(value);
      if (!file) throw Error(str("file \"", value, "\" not found (looked in: ", resolver.describe(), ")"));
      props.setString(name, file->string(), loc);
    } else if (node.tag == "string") props.setString(name, value, loc);
    else throw Error(str("unsupported tag <", node.tag, ">"));
  } catch (const Error& e) {
    if (isEchoed(e)) throw;
    // Properties errors (e.g. a name given twice) carry this element's file:line already.
    throw sceneError(node, messageWithoutLocation(e));
  }
}

}  // namespace femto::xml
