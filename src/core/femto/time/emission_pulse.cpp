#include <femto/time/emission_pulse.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <femto/base/error.h>
#include <femto/core/properties.h>
#include <femto/core/spelling.h>
#include <femto/time/time_grid.h>

namespace femto {
namespace {

/// FWHM of a gaussian over its standard deviation: 2 sqrt(2 ln 2).
const double FwhmPerSigma = 2.0 * std::sqrt(2.0 * std::log(2.0));

double normalCdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }
double normalPdf(double z) { return std::exp(-0.5 * z * z) / std::sqrt(2.0 * 3.14159265358979323846); }

/// The standard normal truncated to [-c, c]: the z with truncated CDF `u`,
/// by Newton steps kept inside a shrinking bracket (bisection when a step
/// leaves it), to double precision.
double truncatedNormalQuantile(double u) {
  const double c = PulseGaussianCutoff, tail = normalCdf(-c), mass = 1.0 - 2.0 * tail;
  const double target = tail + u * mass;
  double lo = -c, hi = c, z = 0.0;
  for (int i = 0; i < 100; ++i) {
    double f = normalCdf(z) - target;
    if (f < 0.0) lo = z; else hi = z;
    double step = f / normalPdf(z), next = z - step;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - z) < 1e-14 * std::max(1.0, std::abs(z))) return next;
    z = next;
  }
  return z;
}

/// An optional length given in OPL (`name`) or seconds (`name`_time); NaN when absent.
double readLength(const Properties& props, const std::string& name) {
  const std::string seconds = name + "_time";
  bool opl = props.has(name), time = props.has(seconds);
  if (opl && time) props.raise(seconds, str("give either ", name, " (OPL) or ", seconds, " (seconds), not both"));
  if (!opl && !time) return std::numeric_limits<double>::quiet_NaN();
  double value = opl ? double(props.getFloat(name)) : double(props.getFloat(seconds)) * SpeedOfLight;
  props.checkRange(opl ? name : seconds, value, Range::finite());
  return value;
}

/// The name actually given for a length (for error messages).
std::string givenName(const Properties& props, const std::string& name) {
  return props.has(name) ? name : name + "_time";
}

double requirePositive(const Properties& props, const std::string& name, double value) {
  props.checkRange(givenName(props, name), value, Range::positive());
  return value;
}

}  // namespace

EmissionPulse EmissionPulse::delta(double offset) { return EmissionPulse(Type::Delta, 0.0, offset); }

EmissionPulse EmissionPulse::gaussian(double sigma, double offset) {
  if (!(sigma > 0.0) || !std::isfinite(sigma)) throw Error(str("gaussian pulse: sigma must be positive, got ", sigma));
  return EmissionPulse(Type::Gaussian, sigma, offset);
}

EmissionPulse EmissionPulse::box(double width, double offset) {
  if (!(width > 0.0) || !std::isfinite(width)) throw Error(str("box pulse: width must be positive, got ", width));
  return EmissionPulse(Type::Box, width, offset);
}

EmissionPulse EmissionPulse::continuous(double offset) { return EmissionPulse(Type::Continuous, 0.0, offset); }

EmissionPulse EmissionPulse::fromProperties(const Properties& props) {
  static const std::vector<std::string> names = {"delta", "gaussian", "box", "continuous"};
  const std::string name = props.getString("pulse", "delta");
  double offset = readLength(props, "pulse_offset");
  if (std::isnan(offset)) offset = 0.0;
  double sigma = readLength(props, "pulse_sigma"), fwhm = readLength(props, "pulse_fwhm");
  double width = readLength(props, "pulse_width");
  // Parameters of another pulse shape are mistakes, not silently ignored.
  auto refuse = [&](const char* parameter, double value, const char* owner) {
    if (!std::isnan(value) && name != owner)
      props.raise(givenName(props, parameter), str("only applies to pulse \"", owner, "\" (this emitter's pulse is \"",
                                                   name, "\")"));
  };
  if (name == "gaussian") {
    if (!std::isnan(sigma) && !std::isnan(fwhm))
      props.raise(givenName(props, "pulse_fwhm"), "give either pulse_sigma or pulse_fwhm, not both");
    if (std::isnan(sigma) && std::isnan(fwhm))
      throw Error(props.location(), "gaussian pulse: missing parameter \"pulse_sigma\" or \"pulse_fwhm\"");
    if (!std::isnan(fwhm)) sigma = requirePositive(props, "pulse_fwhm", fwhm) / FwhmPerSigma;
    requirePositive(props, "pulse_sigma", sigma);
    refuse("pulse_width", width, "box");
    return gaussian(sigma, offset);
  }
  refuse("pulse_sigma", sigma, "gaussian");
  refuse("pulse_fwhm", fwhm, "gaussian");
  if (name == "box") {
    if (std::isnan(width)) throw Error(props.location(), "box pulse: missing parameter \"pulse_width\"");
    return box(requirePositive(props, "pulse_width", width), offset);
  }
  refuse("pulse_width", width, "box");
  if (name == "delta") return delta(offset);
  if (name == "continuous") return continuous(offset);
  props.raise("pulse", str("unknown pulse \"", name, "\"", didYouMean(name, names),
                           "; expected \"delta\", \"gaussian\", \"box\" or \"continuous\""));
}

double EmissionPulse::earliest() const {
  return type_ == Type::Gaussian ? offset_ - PulseGaussianCutoff * width_ : offset_;
}

double EmissionPulse::latest() const {
  switch (type_) {
    case Type::Delta: return offset_;
    case Type::Gaussian: return offset_ + PulseGaussianCutoff * width_;
    case Type::Box: return offset_ + width_;
    case Type::Continuous: break;
  }
  return std::numeric_limits<double>::infinity();
}

double EmissionPulse::sampleOffset(double u) const {
  switch (type_) {
    case Type::Delta: return offset_;
    case Type::Gaussian: return offset_ + width_ * truncatedNormalQuantile(u);
    case Type::Box: return offset_ + width_ * u;
    case Type::Continuous: break;
  }
  throw Error("a continuous emission pulse cannot be sampled (it is not normalisable): deposit it as a step "
              "(RadianceRecorder::addPulsed)");
}

const char* EmissionPulse::name() const {
  switch (type_) {
    case Type::Delta: return "delta";
    case Type::Gaussian: return "gaussian";
    case Type::Box: return "box";
    case Type::Continuous: return "continuous";
  }
  return "?";
}

std::string EmissionPulse::toString() const {
  switch (type_) {
    case Type::Gaussian: return str("gaussian(sigma=", width_, ", offset=", offset_, ")");
    case Type::Box: return str("box(width=", width_, ", offset=", offset_, ")");
    default: return str(name(), "(offset=", offset_, ")");
  }
}

}  // namespace femto
