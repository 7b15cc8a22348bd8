// Test-only transient integrator with a known answer: a camera sample whose
// ray starts at film position (px, py) (see test_film_position.cpp) reports
// `value` at OPL floor(px) + offset ("point"), or spread over
// [floor(px) + offset, floor(px) + offset + length] ("interval"). A film with
// start_opl 0 and bin_width_opl 1 then holds pixel column x in bin x.
//
// | name    | type   | default        | meaning                          |
// |---------|--------|----------------|----------------------------------|
// | mode    | string | "point"        | "point" or "interval"            |
// | offset  | float  | 0.5            | OPL added to the pixel column    |
// | length  | float  | 1              | interval length (interval mode)  |
// | value   | rgb    | 1, 0.5, 0.25   | total contribution of a sample   |
// | jitter  | float  | 0              | adds jitter * sampler.next1D()   |
#include <cmath>

#include <femto/core/plugin.h>
#include <femto/render/sampler.h>
#include <femto/render/transient_integrator.h>

namespace femto::test {

class TransientRampIntegrator final : public TransientIntegrator {
 public:
  explicit TransientRampIntegrator(const Properties& props) {
    std::string mode = props.getString("mode", "point");
    if (mode != "point" && mode != "interval") props.raise("mode", "expected \"point\" or \"interval\"");
    interval_ = mode == "interval";
    offset_ = props.getFloat("offset", 0.5f);
    length_ = props.getFloat("length", 1.0f);
    value_ = props.getColor("value", Color3f(1.0f, 0.5f, 0.25f));
    jitter_ = props.getFloat("jitter", 0.0f);
  }

  void sample(const Scene&, const Ray& ray, Sampler& sampler, RadianceRecorder& recorder) const override {
    // Random times make the film's sums depend on the summation order (the
    // determinism test needs that to mean anything).
    double t0 = std::floor(double(ray.o.x)) + offset_ + (jitter_ > 0.0 ? jitter_ * sampler.next1D() : 0.0);
    if (interval_)
      recorder.addInterval(t0, t0 + length_, value_);
    else
      recorder.add(t0, value_);
  }

  std::string toString() const override { return "TransientRampIntegrator[]"; }

 private:
  bool interval_ = false;
  double offset_, length_, jitter_;
  Color3f value_;
};

}  // namespace femto::test

FEMTO_EXPORT_PLUGIN(femto::test::TransientRampIntegrator, Integrator, "test_transient_ramp",
                    "test-only transient integrator: value at OPL = pixel column")
