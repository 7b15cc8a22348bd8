#pragma once
// A RadianceRecorder that keeps every (OPL, value) contribution of a camera
// sample (and the pulse of its emitter): the unit-test harness of transient integrators.
#include <utility>
#include <vector>

#include <femto/render/transient_integrator.h>

namespace femto::test {

class CollectingRecorder final : public RadianceRecorder {
 public:
  explicit CollectingRecorder(double horizon = Infinity) : horizon_(horizon) {}
  /// A recorder of a transient film's window: `grid`, with horizon grid.end()
  /// (a box time filter); it keeps every contribution, in the window or not.
  explicit CollectingRecorder(const TimeGrid& grid) : horizon_(grid.end()), grid_(grid) {}
  void add(double opl, const Color3f& value) override { addPulsed(opl, opl, value, EmissionPulse()); }
  void addInterval(double opl0, double opl1, const Color3f& value) override {
    addPulsed(opl0, opl1, value, EmissionPulse());
  }
  /// Kept at the interval's midpoint plus the pulse's offset; the pulse in `pulses`.
  void addPulsed(double opl0, double opl1, const Color3f& value, const EmissionPulse& pulse) override {
    hits.emplace_back(0.5 * (opl0 + opl1) + pulse.offset(), value);
    pulses.push_back(pulse);
  }
  double horizon() const override { return horizon_; }
  const TimeGrid& timeGrid() const override { return grid_; }

  Color3f total() const {
    Color3f sum(0.0f);
    for (const auto& h : hits) sum += h.second;
    return sum;
  }

  std::vector<std::pair<double, Color3f>> hits;
  std::vector<EmissionPulse> pulses;  // of each hit

 private:
  double horizon_;
  TimeGrid grid_;
};

inline const TransientIntegrator& transientIntegrator(const Scene& scene) {
  auto integrator = dynamic_cast<const TransientIntegrator*>(&scene.integrator());
  if (!integrator) throw Error("the scene's integrator is not a TransientIntegrator");
  return *integrator;
}

}  // namespace femto::test
