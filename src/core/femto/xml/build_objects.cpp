#include "build_objects.h"

#include <femto/core/log.h>

#include "scene_error.h"
#include "value_properties.h"

namespace femto::xml {
namespace {

/// Command-line overrides for this kind of object: --resolution for films, --spp for samplers.
std::vector<std::pair<std::string, int64_t>> overridesFor(ObjectKind kind, const LoadOptions& options) {
  if (kind == ObjectKind::Film && options.resolution)
    return {{"width", options.resolution->x}, {"height", options.resolution->y}};
  if (kind == ObjectKind::Sampler && options.sampleCount) return {{"sample_count", *options.sampleCount}};
  return {};
}

/// Mitsuba's default children that the command-line overrides reach: a
/// sensor without <film> gets an hdrfilm, one without <sampler> an
/// independent sampler, a scene without <sensor> a perspective camera
/// (render/default_child.h makes the same ones). Made by the plugins, they
/// would not see --resolution or --spp, which would then be ignored without a
/// word; so when an override reaches one, the loader makes it.
struct DefaultChild {
  ObjectKind parent, child;
  const char* plugin;
};
constexpr DefaultChild DefaultChildren[] = {
    {ObjectKind::Sensor, ObjectKind::Film, "hdrfilm"},
    {ObjectKind::Sensor, ObjectKind::Sampler, "independent"},
    {ObjectKind::Scene, ObjectKind::Sensor, "perspective"},
};

/// Whether an override applies to an object of `kind` or to a default child of it.
bool overridesReach(ObjectKind kind, const LoadOptions& options) {
  if (!overridesFor(kind, options).empty()) return true;
  for (const DefaultChild& d : DefaultChildren)
    if (d.parent == kind && overridesReach(d.child, options)) return true;
  return false;
}

/// Whether `node` or anything inside it (following <ref>s) is a <tag>: a
/// sensor nested in a shape counts as the scene's (render/scene.cpp).
bool containsTag(const XmlNode& node, const std::string& tag) {
  if (node.tag == tag) return true;
  for (const auto& child : node.children)
    if (containsTag(child.tag == "ref" && child.target ? *child.target : child, tag)) return true;
  return false;
}

bool isOverridden(const std::vector<std::pair<std::string, int64_t>>& overrides, const std::string& name) {
  for (const auto& o : overrides)
    if (o.first == name) return true;
  return false;
}

/// What messages call an unnamed child object, in the words of the file:
/// `nested <medium type="homogeneous" id="fog"> (line 4)`, or `referenced
/// ...` for a <ref> (with the line the object is declared on), so that the
/// loader's generated key ("_arg_0") never reaches the user.
std::string describeUnnamedChild(const XmlNode& child, const XmlNode& object) {
  std::string tag = str("<", object.tag);
  for (const char* attribute : {"type", "id"})
    if (const std::string* value = object.attribute(attribute); value && !value->empty())
      tag += str(" ", attribute, "=\"", *value, "\"");
  tag += ">";
  std::string where =
      object.location.file == child.location.file ? str("line ", object.location.line) : object.location.toString();
  return str(child.tag == "ref" ? "referenced " : "nested ", tag, " (", where, ")");
}

}  // namespace

Properties ObjectBuilder::properties(const XmlNode& node) {
  auto kind = kindFromTag(node.tag);
  if (!kind) throw sceneError(node, str("<", node.tag, "> is not an object"));
  Properties props;
  if (*kind != ObjectKind::Scene) {
    const std::string* type = node.attribute("type");
    if (!type || type->empty()) throw sceneError(node, str("<", node.tag, "> needs a type=\"...\" attribute"));
    props.setPluginName(*type);
  } else {
    props.setPluginName("scene");
  }
  props.setId(node.attributeOr("id", ""));
  props.setLocation(node.location);

  auto overrides = overridesFor(*kind, options_);
  size_t unnamed = 0;
  for (const auto& child : node.children) {
    const std::string* name = child.attribute("name");
    if (isValueTag(child.tag)) {
      if (name && isOverridden(overrides, *name)) continue;
      addValueProperty(props, child, expanded_.resolver);
      continue;
    }
    const XmlNode* objectNode = nullptr;
    if (child.tag == "ref")
      objectNode = child.target;
    else if (kindFromTag(child.tag) && child.tag != "scene")
      objectNode = &child;
    if (!objectNode) {
      throw sceneError(
          child, str("unsupported tag <", child.tag, ">", child.tag == "scene" ? " (a <scene> cannot be nested)" : ""));
    }
    // Objects at the top of the scene that something references belong to
    // their referrers (e.g. an area emitter attached to a shape by <ref>).
    if (*kind == ObjectKind::Scene && child.tag != "ref" && index_.referenced.count(child.attributeOr("id", "")))
      continue;
    ObjectRef object = build(*objectNode);
    const bool named = name && !name->empty();
    std::string key = named ? *name : str("_arg_", unnamed++);
    try {
      props.setObject(key, object, child.location, named ? std::string() : describeUnnamedChild(child, *objectNode));
    } catch (const Error& e) {
      throw expanded_.sources.addEcho(e, child);
    }
  }
  for (const auto& [name, value] : overrides) props.setInt(name, value, node.location);
  addOverriddenDefaults(*kind, props, &node);
  return props;
}

void ObjectBuilder::addOverriddenDefaults(ObjectKind kind, Properties& props, const XmlNode* node) {
  for (const DefaultChild& d : DefaultChildren) {
    if (d.parent != kind || !props.objectsOfKind(d.child).empty() || !overridesReach(d.child, options_)) continue;
    if (node && containsTag(*node, kindTag(d.child))) continue;
    Properties child(d.plugin);
    child.setLocation(props.location());
    for (const auto& [name, value] : overridesFor(d.child, options_)) child.setInt(name, value, props.location());
    addOverriddenDefaults(d.child, child, nullptr);
    ObjectRef object;
    try {
      object = factory_.create(d.child, child);
    } catch (const Error& e) {
      throw Error(props.location(), str("the default <", kindTag(d.child), "> (", d.plugin, "): ", e.what()));
    }
    props.setObject(str("_default_", kindTag(d.child)), object, props.location(),
                    str("default <", kindTag(d.child), " type=\"", d.plugin, "\">"));
  }
}

ObjectRef ObjectBuilder::build(const XmlNode& node) {
  if (auto it = built_.find(&node); it != built_.end()) return it->second;
  Properties props = properties(node);
  ObjectKind kind = *kindFromTag(node.tag);
  ObjectRef object;
  try {
    object = factory_.create(kind, props);
  } catch (const Error& e) {
    throw expanded_.sources.addEcho(e, node);
  } catch (const std::exception& e) {
    throw sceneError(node, str("creating \"", props.pluginName(), "\" failed: ", e.what()));
  }
  if (!object) throw sceneError(node, str("plugin \"", props.pluginName(), "\" returned no object"));
  if (!props.id().empty()) object->setId(props.id());
  reportUnused(props, node);
  built_[&node] = object;
  return object;
}

void ObjectBuilder::reportUnused(const Properties& props, const XmlNode& node) const {
  for (const auto& name : props.unqueried()) {
    // Named library objects at the top of a scene (e.g. a <bsdf id> no shape
    // uses) are legal in Mitsuba; they are not parameters of the scene.
    if (props.pluginName() == "scene" && node.tag == "scene" && props.type(name) == Properties::Type::Object &&
        !props.getObject(name)->id().empty())
      continue;
    SourceLocation where = props.location(name);
    std::string message =
        str(props.describe(name), " of \"", props.pluginName(), "\" was not used", props.suggestionFor(name));
    Error error = sceneError(where, expanded_.sources.lineText(where), message);
    if (options_.strict) throw error;
    logWarn(error.what());
  }
}

}  // namespace femto::xml
