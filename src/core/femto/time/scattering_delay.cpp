#include <femto/time/scattering_delay.h>

#include <cmath>

namespace femto {

ScatteringDelay::ScatteringDelay(const Properties& props)
    : delay_(props.getFloat("delay", 0.0f, Range::nonNegative())),
      lifetime_(props.getFloat("lifetime", 0.0f, Range::nonNegative())) {
}

double ScatteringDelay::sample(float u) const {
  // Inverse CDF of the exponential distribution with mean `lifetime`.
  double exponential = lifetime_ > 0.0 ? -lifetime_ * std::log1p(-double(u)) : 0.0;
  return delay_ + exponential;
}

std::string ScatteringDelay::toString() const {
  if (!any()) return "";
  return str(", delay=", delay_, ", lifetime=", lifetime_);
}

}  // namespace femto
