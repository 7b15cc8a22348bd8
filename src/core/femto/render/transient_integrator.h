#pragma once
// Transient (time-resolved) integrators report every contribution of a camera
// sample together with the optical path length (OPL, see time_grid.h) at which
// it reaches the sensor. The core's render loop routes those contributions to
// a transient film (binned in time) or, for a steady film, just sums them, so
// the same integrator renders both.
#include <functional>
#include <memory>
#include <optional>

#include <femto/math/constants.h>
#include <femto/math/ray.h>
#include <femto/math/spectrum.h>
#include <femto/render/integrator.h>
#include <femto/time/emission_pulse.h>
#include <femto/time/time_deposit.h>
#include <femto/time/time_grid.h>

namespace femto {

class Scene;
class Sampler;

/// Receives the contributions of one camera sample (one film position).
class RadianceRecorder {
 public:
  virtual ~RadianceRecorder() = default;
  /// Radiance `value` arriving at optical path length `opl`.
  virtual void add(double opl, const Color3f& value) = 0;
  /// Radiance whose total is `value`, spread uniformly over [opl0, opl1]
  /// (photon-beam estimates cover an interval; opl0 == opl1 behaves like add()).
  virtual void addInterval(double opl0, double opl1, const Color3f& value) = 0;
  /// A contribution over [opl0, opl1] (a point when equal) computed for a
  /// Dirac emission at OPL 0, from an emitter that emits with `pulse`
  /// (Emitter::pulse()): the film deposits it convolved with the pulse,
  /// exactly (TimeDeposit::pulsed). Its steady total is `value` for every
  /// pulse. The default handles delta pulses (add/addInterval at the shifted
  /// OPL) and refuses others; film and steady recorders override it.
  virtual void addPulsed(double opl0, double opl1, const Color3f& value, const EmissionPulse& pulse);
  /// Contributions at OPL >= horizon() cannot reach the film's window: an
  /// integrator may stop a path once its OPL passes it (Infinity for steady
  /// films). It allows for the scene's emitter pulses: a path whose Dirac
  /// OPL is tau reaches the film from tau + the earliest pulse offset on.
  virtual double horizon() const = 0;
  /// The film's time axis (bins == 0 for steady films).
  virtual const TimeGrid& timeGrid() const = 0;
};

/// The recorder of steady films: the time of arrival is irrelevant, so the
/// contributions are summed (no bookkeeping: a transient integrator then costs
/// what a SamplingIntegrator does). Pulses are normalised (a continuous
/// emitter's steady image is its total), so they do not change the sum.
class SteadySumRecorder final : public RadianceRecorder {
 public:
  void add(double, const Color3f& value) override { sum += value; }
  void addInterval(double, double, const Color3f& value) override { sum += value; }
  void addPulsed(double, double, const Color3f& value, const EmissionPulse&) override { sum += value; }
  double horizon() const override { return Infinity; }
  const TimeGrid& timeGrid() const override { return grid_; }
  Color3f sum{0.0f};

 private:
  TimeGrid grid_;  // bins == 0: steady
};

class TransientIntegrator : public Integrator {
 public:
  /// Trace one camera sample along `ray` (OPL 0 at the sensor) and report its
  /// contributions to `recorder`.
  virtual void sample(const Scene& scene, const Ray& ray, Sampler& sampler, RadianceRecorder& recorder) const = 0;
  /// Does the OPL an integrator reports include the camera segment (observer
  /// time)? If not, a film's near-clip time origin does not apply to it.
  virtual bool countsCameraSegment() const { return true; }
  /// The steady radiance of one camera sample along `ray`: the sum of what
  /// sample() reports (SteadySumRecorder).
  Color3f steadyRadiance(const Scene& scene, const Ray& ray, Sampler& sampler) const;
  /// Drives the film: transient films get a time-binned volume (streamed),
  /// steady films the ordinary image.
  RenderStats render(const Scene& scene, const RenderOptions& options) const override;

  /// The time filter this integrator asks the film to use (mitransient's
  /// temporal_filter), or none: the film's own. The scene hands it over.
  const std::optional<TimeFilter>& requestedTimeFilter() const { return requestedTimeFilter_; }
  /// Where the scene asked for it (for messages).
  const SourceLocation& requestedTimeFilterAt() const { return requestedTimeFilterAt_; }

 protected:
  /// mitransient's temporal filter on the integrator: temporal_filter = ""
  /// (the film's own), "box" or "gaussian" with gaussian_stddev (bins,
  /// default 2).
  void readTemporalFilter(const Properties& props);

 private:
  std::optional<TimeFilter> requestedTimeFilter_;
  SourceLocation requestedTimeFilterAt_;
};

}  // namespace femto
