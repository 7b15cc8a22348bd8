// Mitsuba's mitchell, catmullrom and lanczos pixel filters: the closed forms
// at known points (Mitchell and Netravali 1988, eq. 8), continuity at the
// knots, unit integral of the B + 2C = 1 family, sinc zeros, and errors.
#include <gtest/gtest.h>

#include <cmath>

#include <femto/render/rfilter.h>

#include "plugin_util.h"
#include "render_test_util.h"

namespace femto {
namespace {

std::shared_ptr<ReconstructionFilter> filter(const std::string& type, Properties props = Properties()) {
  props.setPluginName(type);
  return test::makePlugin<ReconstructionFilter>(ObjectKind::ReconstructionFilter, props);
}

double integral(const ReconstructionFilter& f) {
  const int n = 200000;
  double sum = 0.0, h = 2.0 * f.radius() / n;
  for (int i = 0; i < n; ++i) sum += f.eval(float(-f.radius() + (i + 0.5) * h));
  return sum * h;
}

}  // namespace

TEST(CubicFilters, MitchellMatchesTheClosedFormAndIntegratesToOne) {
  auto m = filter("mitchell");
  EXPECT_FLOAT_EQ(m->radius(), 2.0f);
  const float b = 1.0f / 3.0f;
  EXPECT_NEAR(m->eval(0.0f), (6.0f - 2.0f * b) / 6.0f, 1e-6f);  // 8/9
  EXPECT_NEAR(m->eval(2.0f), 0.0f, 1e-6f);
  EXPECT_NEAR(m->eval(1.0f - 1e-4f), m->eval(1.0f + 1e-4f), 1e-3f);  // continuous at the knot
  EXPECT_NEAR(m->eval(0.7f), m->eval(-0.7f), 0.0f);
  EXPECT_NEAR(integral(*m), 1.0, 1e-4);  // B + 2C = 1
  EXPECT_LT(m->eval(1.5f), 0.0f) << "the negative lobe";
}

TEST(CubicFilters, CatmullRomInterpolates) {
  auto c = filter("catmullrom");
  EXPECT_NEAR(c->eval(0.0f), 1.0f, 1e-6f);
  EXPECT_NEAR(c->eval(1.0f), 0.0f, 1e-6f);
  EXPECT_NEAR(integral(*c), 1.0, 1e-4);
  Properties wider;
  wider.setFloat("radius", 3.0f);
  auto w = filter("catmullrom", wider);
  EXPECT_NEAR(w->eval(1.5f), c->eval(1.0f), 1e-6f) << "the radius stretches the same curve";
}

TEST(CubicFilters, LanczosIsAWindowedSinc) {
  auto l = filter("lanczos");
  EXPECT_FLOAT_EQ(l->radius(), 3.0f);
  EXPECT_NEAR(l->eval(0.0f), 1.0f, 1e-6f);
  for (float x : {1.0f, 2.0f}) EXPECT_NEAR(l->eval(x), 0.0f, 1e-6f);
  float x = 0.5f;
  EXPECT_NEAR(l->eval(x), std::sin(Pi * x) / (Pi * x) * std::sin(Pi * x / 3.0f) / (Pi * x / 3.0f), 1e-6f);
  EXPECT_EQ(l->eval(3.5f), 0.0f);
  Properties bad;
  bad.setInt("lobes", 0);
  std::string message = test::errorMessageOf([&] { filter("lanczos", bad); });
  EXPECT_NE(message.find("lobes"), std::string::npos) << message;
}

}  // namespace femto
