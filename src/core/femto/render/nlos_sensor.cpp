#include <femto/render/nlos_sensor.h>

namespace femto {

// Out of line: the class's type information then lives in the core, once, for
// dynamic_cast across plugin libraries.
NlosSensor::~NlosSensor() = default;

}  // namespace femto
