#pragma once
// Participating media. Only the object kind exists so far: shapes and sensors
// can already reference media; sampling and transmittance arrive with the
// time-resolved rendering work (issue 4).
#include <femto/core/object.h>

namespace femto {

class Medium : public Object {
 public:
  ObjectKind kind() const override { return ObjectKind::Medium; }
};

}  // namespace femto
