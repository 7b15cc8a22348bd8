#pragma once
// The temporal profile of an emitter: when, relative to the transient film's
// OPL 0, it emits (Marco et al., "Transient Photon Beams": every photon
// carries its emission time from the emitter's pulse; SEED.md: Dirac vs
// continuous emission). Every emitter reads one (Emitter::pulse()); times are
// optical path lengths (OPL = c t, scene units, see time_grid.h).
//
//   delta       emits everything at `offset` (the default: offset 0)
//   gaussian    density N(offset, sigma^2), truncated at +-4 sigma and renormalised
//               (as the film's gaussian time filter), so its support is finite
//   box         uniform over [offset, offset + width]
//   continuous  a step: emits at a constant rate from `offset` on
//
// delta, gaussian and box are normalised to total 1: the steady image is the
// same whatever the pulse. continuous is not a distribution: its transient at
// time t is the *running integral* of the Dirac transient up to t, so once all
// light has arrived a frame equals the steady image (which is the total, as
// for the other pulses).
//
// How pulses are realised: camera integrators report contributions for a
// Dirac emission together with the emitter's pulse (RadianceRecorder::addPulsed)
// and the film deposits the exact convolution on its time axis
// (TimeDeposit::pulsed), with no extra noise. Photon integrators instead give
// each photon an emission time sampleOffset(u), exact in expectation; a
// continuous pulse cannot be sampled and is realised by the film's step
// deposit there too. See docs/transient-film.md, "Emitter pulses".
#include <string>

namespace femto {

class Properties;

class EmissionPulse {
 public:
  enum class Type { Delta, Gaussian, Box, Continuous };

  /// Default: a Dirac pulse at OPL 0.
  EmissionPulse() = default;
  static EmissionPulse delta(double offset = 0.0);
  /// Standard deviation `sigma` (OPL, > 0) centred on `offset`.
  static EmissionPulse gaussian(double sigma, double offset = 0.0);
  /// Uniform over [offset, offset + width] (width > 0).
  static EmissionPulse box(double width, double offset = 0.0);
  /// A step switched on at `offset`.
  static EmissionPulse continuous(double offset = 0.0);

  /// Reads an emitter's pulse parameters (all optional):
  ///   pulse        string  delta | gaussian | box | continuous   (default delta)
  ///   pulse_sigma  float   gaussian: standard deviation, OPL   } exactly one of the two
  ///   pulse_fwhm   float   gaussian: full width at half maximum } (2 sqrt(2 ln 2) sigma)
  ///   pulse_width  float   box: duration, OPL (required)
  ///   pulse_offset float   delta: the instant; gaussian: centre; box, continuous: start (default 0)
  /// Each length may instead be given in seconds with the suffix `_time`
  /// (pulse_sigma_time, ...; OPL = c t with the scene in metres), as the
  /// transient film's bin_width_time. Errors (naming the parameter): unknown
  /// pulse names (with a "did you mean"), non-positive or non-finite widths,
  /// both sigma and fwhm, a value in both units, a parameter the pulse does not use.
  static EmissionPulse fromProperties(const Properties& props);

  Type type() const { return type_; }
  bool isDelta() const { return type_ == Type::Delta; }
  bool isContinuous() const { return type_ == Type::Continuous; }
  /// Gaussian: standard deviation; box: width; 0 otherwise (OPL).
  double width() const { return width_; }
  double offset() const { return offset_; }
  /// Earliest emission OPL: a contribution reported at OPL tau reaches the
  /// film no earlier than tau + earliest() (gaussian: offset - 4 sigma).
  double earliest() const;
  /// Latest emission OPL (Infinity for continuous).
  double latest() const;

  /// An emission OPL distributed as the pulse, from u in [0, 1) (inversion;
  /// photon tracing). delta: offset. Throws for continuous, which has no
  /// normalised density: photon integrators realise it by the film's step deposit.
  double sampleOffset(double u) const;

  const char* name() const;
  std::string toString() const;
  bool operator==(const EmissionPulse& o) const {
    return type_ == o.type_ && width_ == o.width_ && offset_ == o.offset_;
  }

 private:
  EmissionPulse(Type type, double width, double offset) : type_(type), width_(width), offset_(offset) {}
  Type type_ = Type::Delta;
  double width_ = 0.0, offset_ = 0.0;
};

/// Truncation of the gaussian pulse, in standard deviations.
inline constexpr double PulseGaussianCutoff = 4.0;

}  // namespace femto
