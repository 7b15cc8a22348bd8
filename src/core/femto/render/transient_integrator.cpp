#include <femto/render/transient_integrator.h>

#include <algorithm>
#include <cmath>

#include <femto/base/error.h>

namespace femto {

void RadianceRecorder::addPulsed(double opl0, double opl1, const Color3f& value, const EmissionPulse& pulse) {
  if (!pulse.isDelta()) throw Error(str("this radiance recorder cannot deposit a ", pulse.name(), " emission pulse"));
  if (opl0 == opl1)
    add(opl0 + pulse.offset(), value);
  else
    addInterval(opl0 + pulse.offset(), opl1 + pulse.offset(), value);
}

Color3f TransientIntegrator::steadyRadiance(const Scene& scene, const Ray& ray, Sampler& sampler) const {
  SteadySumRecorder recorder;
  sample(scene, ray, sampler, recorder);
  return recorder.sum;
}

void TransientIntegrator::readTemporalFilter(const Properties& props) {
  enum class Kind { Film, Box, Gaussian };
  const Kind kind = props.getEnum("temporal_filter", Kind::Film,
                                  {{"box", Kind::Box}, {"gaussian", Kind::Gaussian}, {"", Kind::Film, "the film's own"}});
  float stddev = props.getFloat("gaussian_stddev", 2.0f);
  if (kind == Kind::Film) return;
  if (kind == Kind::Box) {
    requestedTimeFilter_ = TimeFilter::box();
  } else {
    props.checkRange("gaussian_stddev", stddev, Range::positive(), "bins");
    requestedTimeFilter_ = TimeFilter::gaussian(stddev);
  }
  requestedTimeFilterAt_ = props.location("temporal_filter");
}

}  // namespace femto
