#pragma once
// The object every test-only plugin creates: a texture-kind Object that reads
// one float, so tests can see the Properties reached the plugin.
#include <femto/core/object.h>
#include <femto/core/properties.h>

namespace femto::test {

class TestTexture : public Object {
 public:
  explicit TestTexture(const Properties& props) : value_(props.getFloat("value", 1.0f)) {}
  ObjectKind kind() const override { return ObjectKind::Texture; }
  float value() const { return value_; }

 private:
  float value_;
};

}  // namespace femto::test
