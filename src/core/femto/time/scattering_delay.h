#pragma once
// Time spent in a scattering event (the transient RTE's time-dependent
// scattering, Marco et al. 2017, "Transient Photon Beams", eq. 2): a constant
// delay plus an exponentially distributed, fluorescence-like lifetime. Phase
// functions and BSDFs both read it:
//
// | name     | type  | default | meaning                                               | unit |
// |----------|-------|---------|-------------------------------------------------------|------|
// | delay    | float | 0       | constant extra optical path added at every scattering | OPL  |
// | lifetime | float | 0       | mean of an exponentially distributed extra delay      | OPL  |
#include <string>

#include <femto/core/properties.h>

namespace femto {

class ScatteringDelay {
 public:
  ScatteringDelay() = default;
  /// Reads "delay" and "lifetime" (finite, >= 0).
  explicit ScatteringDelay(const Properties& props);

  /// delay + an exponential variate of mean lifetime, from u in [0, 1).
  double sample(float u) const;
  /// Does scattering take time at all? (Integrators draw no random number otherwise.)
  bool any() const { return delay_ > 0.0 || lifetime_ > 0.0; }
  /// ", delay=..., lifetime=..." for toString(); "" when both are 0.
  std::string toString() const;

 private:
  double delay_ = 0.0, lifetime_ = 0.0;
};

}  // namespace femto
