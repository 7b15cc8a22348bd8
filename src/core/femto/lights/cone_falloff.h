#pragma once
// Mitsuba's angular falloff of spot lights (and mitransient's angulararea
// emitter): full strength within beam_width of the axis, then falling
// linearly in angle to zero at cutoff_angle.
#include <algorithm>
#include <cmath>

#include <femto/core/log.h>
#include <femto/core/properties.h>
#include <femto/math/constants.h>

namespace femto {

class ConeFalloff {
 public:
  /// Reads cutoff_angle (degrees, in (0, 90]; default `defaultCutoffDeg`) and
  /// beam_width (degrees; default `defaultBeamFraction` x cutoff). A beam
  /// wider than the cutoff is, as in Mitsuba, a warning and the cutoff.
  ConeFalloff(const Properties& props, float defaultCutoffDeg, float defaultBeamFraction) {
    float cutoffDeg = props.getFloat("cutoff_angle", defaultCutoffDeg, Range::leftOpen(0, 90), "degrees");
    float beamDeg = props.getFloat("beam_width", cutoffDeg * defaultBeamFraction, Range::nonNegative(), "degrees");
    if (beamDeg > cutoffDeg) {
      SourceLocation where = props.location("beam_width");
      logWarn(where.known() ? where.toString() + ": " : "", props.pluginName(), " beam_width ", beamDeg,
              " exceeds cutoff_angle ", cutoffDeg, "; using the cutoff angle");
      beamDeg = cutoffDeg;
    }
    cutoff_ = degToRad(cutoffDeg);
    beamWidth_ = degToRad(beamDeg);
    cosCutoff_ = std::cos(cutoff_);
    cosBeamWidth_ = std::cos(beamWidth_);
  }

  /// The falloff at angle acos(cosTheta) from the axis, in [0, 1].
  float operator()(float cosTheta) const {
    if (!(cosTheta > cosCutoff_)) return 0.0f;
    if (cosTheta >= cosBeamWidth_) return 1.0f;
    return (cutoff_ - std::acos(std::min(cosTheta, 1.0f))) / (cutoff_ - beamWidth_);
  }

  /// Integral of the falloff over the sphere, with b = beam_width, c = cutoff:
  ///   2 pi [ (1 - cos b) + int_b^c (c - t) / (c - b) sin t dt ]
  ///   = 2 pi [ 1 + (sin b - sin c) / (c - b) ],
  /// which tends to 2 pi (1 - cos c) as b -> c. In double: the difference
  /// quotient cancels digits for a narrow soft edge.
  float solidAngle() const {
    double b = beamWidth_, c = cutoff_, width = c - b;
    return float(width > 1e-6 ? 2.0 * Pi * (1.0 + (std::sin(b) - std::sin(c)) / width)
                              : 2.0 * Pi * (1.0 - std::cos(0.5 * (b + c))));
  }

  /// Integral of falloff x cos(theta) over the hemisphere (for emitters on a
  /// surface): 2 pi [ sin^2 b / 2 + int_b^c (c - t) / (c - b) sin t cos t dt ]
  ///   = pi sin^2 b + 2 pi [ cos 2b / 4 - (sin 2c - sin 2b) / (8 (c - b)) ]
  /// (by parts), which tends to pi sin^2 c as b -> c.
  float projectedSolidAngle() const {
    double b = beamWidth_, c = cutoff_, width = c - b;
    if (!(width > 1e-6)) {
      double s = std::sin(0.5 * (b + c));
      return float(Pi * s * s);
    }
    double sinB = std::sin(b);
    return float(Pi * sinB * sinB + 2.0 * Pi * (0.25 * std::cos(2.0 * b) - (std::sin(2.0 * c) - std::sin(2.0 * b)) / (8.0 * width)));
  }

  float cutoff() const { return cutoff_; }
  float beamWidth() const { return beamWidth_; }
  float cosCutoff() const { return cosCutoff_; }

 private:
  float cutoff_ = 0.0f, beamWidth_ = 0.0f, cosCutoff_ = 1.0f, cosBeamWidth_ = 1.0f;
};

}  // namespace femto
