#pragma once
// A RadianceRecorder that keeps every (OPL, value) contribution of a camera
// sample: the unit-test harness of transient integrators.
#include <utility>
#include <vector>

#include <femto/render/transient_integrator.h>

namespace femto::test {

class CollectingRecorder final : public RadianceRecorder {
 public:
  explicit CollectingRecorder(double horizon = Infinity) : horizon_(horizon) {}
  void add(double opl, const Color3f& value) override { hits.emplace_back(opl, value); }
  void addInterval(double opl0, double opl1, const Color3f& value) override {
    hits.emplace_back(0.5 * (opl0 + opl1), value);
  }
  double horizon() const override { return horizon_; }
  const TimeGrid& timeGrid() const override { return grid_; }

  Color3f total() const {
    Color3f sum(0.0f);
    for (const auto& h : hits) sum += h.second;
    return sum;
  }

  std::vector<std::pair<double, Color3f>> hits;

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
