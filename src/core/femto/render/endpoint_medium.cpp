#include <femto/render/endpoint_medium.h>

#include <femto/render/medium.h>

namespace femto {

std::shared_ptr<Medium> endpointMedium(const Properties& props) {
  if (props.has("medium")) {
    auto medium = std::dynamic_pointer_cast<Medium>(props.getObject("medium"));
    if (!medium) props.raise("medium", "expected a <medium>");
    // A second, unnamed medium is left unread and reported as unused.
    return medium;
  }
  return props.object<Medium>(ObjectKind::Medium);
}

}  // namespace femto
