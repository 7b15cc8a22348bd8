// Directions sampled around a point (transport/point_directions.h): the
// density integrates to one over the sphere and is zero on the hemisphere
// facing away; the samples follow it (the angle to the point is uniform on
// [0, pi/2), the azimuth uniform); the density the sampler reports is the one
// pdfPointDirection evaluates, also at the small angles that carry the MIS
// weights of rays passing close to the point.
#include <gtest/gtest.h>

#include <cmath>

#include <femto/math/constants.h>
#include <femto/math/frame.h>
#include <femto/math/pcg32.h>
#include <femto/transport/point_directions.h>

using namespace femto;

namespace {

const Point3f Y(0.3f, -0.2f, 0.5f), C(1.1f, 0.7f, -0.4f);

}  // namespace

TEST(PointDirections, DensityIntegratesToOneOverTheSphere) {
  // Midpoint rule in (cos theta, phi) about the axis to C: the 1/sin alpha
  // singularity is integrable; the grid starts half a cell off the axis.
  Vec3f axis = normalize(C - Y);
  Frame frame(axis);
  const int nTheta = 4000, nPhi = 64;
  double integral = 0.0, behind = 0.0;
  for (int i = 0; i < nTheta; ++i) {
    double alpha = (i + 0.5) / nTheta * Pi;
    for (int j = 0; j < nPhi; ++j) {
      double phi = (j + 0.5) / nPhi * 2.0 * Pi;
      Vec3f w = frame.toWorld(Vec3f(float(std::sin(alpha) * std::cos(phi)), float(std::sin(alpha) * std::sin(phi)),
                                    float(std::cos(alpha))));
      double cell = std::sin(alpha) * (Pi / nTheta) * (2.0 * Pi / nPhi);
      double p = pdfPointDirection(Y, C, normalize(w));
      (alpha < 0.5 * Pi ? integral : behind) += p * cell;
    }
  }
  EXPECT_NEAR(integral, 1.0, 1e-3);
  EXPECT_EQ(behind, 0.0);
}

TEST(PointDirections, SamplesHaveUniformAngleToThePointAndReportTheirDensity) {
  PCG32 rng(5, 1);
  Vec3f axis = normalize(C - Y);
  const int n = 200000, bins = 10;
  std::vector<int> counts(bins, 0);
  for (int i = 0; i < n; ++i) {
    float pdf = 0.0f;
    Vec3f w = samplePointDirection(Y, C, Point2f(rng.nextFloat(), rng.nextFloat()), pdf);
    ASSERT_NEAR(length(w), 1.0f, 1e-5f);
    double alpha = std::atan2(double(length(cross(w, axis))), double(dot(w, axis)));
    ASSERT_LT(alpha, 0.5 * Pi + 1e-5);
    counts[std::min(bins - 1, int(alpha / (0.5 * Pi) * bins))]++;
    // The float direction carries the angle to about 1e-7 (absolute): at tiny
    // angles that is a relative error of 1e-7 / alpha in the density.
    double evaluated = pdfPointDirection(Y, C, w);
    ASSERT_NEAR(pdf, evaluated, (2e-3 + 1e-7 / alpha) * evaluated) << "alpha " << alpha;
  }
  // Uniform alpha: each bin holds n / bins, binomial spread.
  double sigma = std::sqrt(n * (1.0 / bins) * (1.0 - 1.0 / bins));
  for (int b = 0; b < bins; ++b) EXPECT_NEAR(counts[b], n / bins, 5.0 * sigma) << "bin " << b;
}

TEST(PointDirections, DensityIsExactAtSmallAngles) {
  // 1 / (pi^2 sin alpha) for alpha = 1e-5: cos alpha rounds to 1 in float,
  // so a density from cos alpha would be infinite or zero.
  Vec3f axis = normalize(C - Y);
  Frame frame(axis);
  for (double alpha : {1e-5, 1e-4, 1e-2}) {
    Vec3f w = normalize(frame.toWorld(Vec3f(float(std::sin(alpha)), 0.0f, float(std::cos(alpha)))));
    double expected = 1.0 / (Pi * Pi * std::sin(alpha));
    EXPECT_NEAR(pdfPointDirection(Y, C, w), expected, 0.02 * expected) << "alpha " << alpha;
  }
}
