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
  std::string type = props.getString("temporal_filter", "");
  float stddev = props.getFloat("gaussian_stddev", 2.0f);
  if (type.empty()) return;
  if (type == "box") {
    requestedTimeFilter_ = TimeFilter::box();
  } else if (type == "gaussian") {
    if (!(stddev > 0.0f) || !std::isfinite(stddev)) props.raise("gaussian_stddev", str("must be positive (bins), got ", stddev));
    requestedTimeFilter_ = TimeFilter::gaussian(stddev);
  } else {
    props.raise("temporal_filter", str("expected \"box\", \"gaussian\" or \"\" (the film's own), got \"", type, "\""));
  }
  requestedTimeFilterAt_ = props.location("temporal_filter");
}

}  // namespace femto
