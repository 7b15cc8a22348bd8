#pragma once
// The medium a sensor or emitter sits in. Both Mitsubas take it as a nested
// <medium> or a <ref> to one, with or without a name (Mitsuba 0.6:
// AbstractEmitter::addChild; Mitsuba 3: the Endpoint constructor), so
// `<emitter type="point"><ref id="fog"/></emitter>` puts the light in the fog;
// femto's own scenes may also name it "medium".
#include <memory>

#include <femto/core/properties.h>

namespace femto {

class Medium;

/// The endpoint's medium from `props` ("medium", else the single nested
/// <medium> of any name), or nullptr. Two media, or a "medium" that is not
/// one, are errors naming the object.
std::shared_ptr<Medium> endpointMedium(const Properties& props);

}  // namespace femto
