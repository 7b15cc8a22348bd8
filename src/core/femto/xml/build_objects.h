#pragma once
// Parse stage 5: create objects bottom-up from the expanded, resolved tree.
#include <map>
#include <memory>

#include <femto/core/properties.h>
#include <femto/xml/loader.h>

#include "expand_directives.h"
#include "resolve_references.h"
#include "xml_node.h"

namespace femto::xml {

/// Makes one object from its Properties. The real one asks PluginManager (and
/// makes the core Scene for <scene>); tests substitute a double.
class ObjectFactory {
 public:
  virtual ~ObjectFactory() = default;
  /// Throws femto::Error for unknown plugins or plugins of another kind; the
  /// builder adds file:line and the echoed line.
  virtual ObjectRef create(ObjectKind kind, const Properties& props) = 0;
};

/// PluginManager::instance() for plugins, std::make_shared<Scene> for <scene>.
std::unique_ptr<ObjectFactory> makePluginFactory();

class ObjectBuilder {
 public:
  ObjectBuilder(const ExpandResult& expanded, const ObjectIndex& index, const LoadOptions& options,
                ObjectFactory& factory)
      : expanded_(expanded), index_(index), options_(options), factory_(factory) {}

  /// Create the object of `node` (children first; each referenced object once).
  /// Reference cycles were refused by resolveReferences.
  ObjectRef build(const XmlNode& node);
  /// The Properties `node`'s object is created from (nested objects built),
  /// including the --resolution/--spp overrides. Exposed for tests.
  Properties properties(const XmlNode& node);

 private:
  /// Makes the default film, sampler or sensor that a command-line override
  /// reaches and `props` (made from `node`, when given) lacks anywhere
  /// inside (see DefaultChildren in the .cpp).
  void addOverriddenDefaults(ObjectKind kind, Properties& props, const XmlNode* node);
  /// Warn (or, when strict, throw) for parameters the object did not read.
  void reportUnused(const Properties& props, const XmlNode& node) const;

  const ExpandResult& expanded_;
  const ObjectIndex& index_;
  const LoadOptions& options_;
  ObjectFactory& factory_;
  std::map<const XmlNode*, ObjectRef> built_;
};

}  // namespace femto::xml
