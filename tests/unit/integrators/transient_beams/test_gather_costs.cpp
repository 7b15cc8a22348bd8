// transient_beams' derived gather fraction (beam_settings.h, GatherCosts):
// the square root of the rest of a sample's cost over a gather's, scaled by
// RouletteVarianceShare, within [max(1/16, 1/spp), 1].
#include <gtest/gtest.h>

#include <cmath>

#include <transient_beams/beam_settings.h>

using namespace femto;
using namespace femto::beams;

namespace {

GatherCosts costs(double pairs, double photonsPerSample, double spp) {
  GatherCosts c;
  c.gathersPerSample = 1.0;
  c.boxes = 3.0 * pairs, c.candidates = pairs, c.pairs = pairs;
  c.photonsPerSample = photonsPerSample;
  c.samplesPerPixel = spp;
  return c;
}

}  // namespace

TEST(GatherCosts, DearGathersAreMadeLessOftenCheapOnesAlways) {
  // Few pairs per query (the box lit from outside): every segment gathers.
  EXPECT_EQ(costs(5, 6, 16).fraction(), 1.0);
  // More pairs, a smaller fraction, as the inverse square root of the gather's cost.
  const double a = costs(100, 1, 64).fraction(), b = costs(400, 1, 64).fraction();
  EXPECT_LT(b, a);
  EXPECT_LT(a, 1.0);
  const double ratio = a / b;  // the gather's cost grows 4x, the fraction halves (the rest is fixed)
  EXPECT_NEAR(ratio, 2.0, 1e-9);
  // A dearer photon pass per sample (shared by the samples) makes gathers relatively cheaper.
  EXPECT_GT(costs(400, 20, 64).fraction(), b);
}

TEST(GatherCosts, AtLeastOneGatherAPixelPerPass) {
  // However dear, a pixel keeps one gather per pass (1/spp), and never below 1/16.
  EXPECT_EQ(costs(1e6, 0, 2).fraction(), 0.5);
  EXPECT_EQ(costs(1e6, 0, 8).fraction(), 0.125);
  EXPECT_EQ(costs(1e6, 0, 1024).fraction(), MinGatherFraction);
  EXPECT_EQ(costs(1e6, 0, 1).fraction(), 1.0);
  // No gathers at all (no media): nothing to roulette.
  GatherCosts none;
  EXPECT_EQ(none.fraction(), 1.0);
}
