// Error metrics (src/core/femto/analysis/image_metrics.h) against values
// computed by hand from their definitions in docs/compare.md.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <femto/analysis/image_metrics.h>
#include <femto/base/error.h>

namespace femto {
namespace {

// Differences 0.5, 0, -1, 0 against reference values 1, 0, 2, 0.5.
const std::vector<float> RefValues = {1.0f, 0.0f, 2.0f, 0.5f};
const std::vector<float> TestValues = {1.5f, 0.0f, 1.0f, 0.5f};

TEST(ImageMetrics, MseIsTheMeanSquaredDifference) { EXPECT_DOUBLE_EQ(mse(RefValues, TestValues), (0.25 + 1.0) / 4); }

TEST(ImageMetrics, RelMseDividesEachSquaredDifferenceByRefSquaredPlusEpsilon) {
  EXPECT_DOUBLE_EQ(relMse(RefValues, TestValues), (0.25 / (1.0 + 0.01) + 1.0 / (4.0 + 0.01)) / 4);
  EXPECT_DOUBLE_EQ(relMse(RefValues, TestValues, 1.0), (0.25 / 2.0 + 1.0 / 5.0) / 4);
  EXPECT_DOUBLE_EQ(DefaultRelMseEpsilon, 0.01);
}

TEST(ImageMetrics, MaeAndMaxErrorUseAbsoluteDifferences) {
  EXPECT_DOUBLE_EQ(mae(RefValues, TestValues), 1.5 / 4);
  EXPECT_DOUBLE_EQ(maxError(RefValues, TestValues), 1.0);
  EXPECT_DOUBLE_EQ(mae(TestValues, RefValues), 1.5 / 4);  // symmetric in the difference
}

TEST(ImageMetrics, PsnrIsTenLog10PeakSquaredOverMse) {
  EXPECT_DOUBLE_EQ(psnr(0.3125, 2.0), 10.0 * std::log10(4.0 / 0.3125));
  EXPECT_EQ(psnr(0.0, 1.0), std::numeric_limits<double>::infinity());
  ErrorMetrics m = errorMetrics(RefValues, TestValues);
  EXPECT_DOUBLE_EQ(m.referencePeak, 2.0);
  EXPECT_EQ(m.count, 4u);
}

TEST(ImageMetrics, IdenticalInputsHaveZeroError) {
  ErrorMetrics m = errorMetrics(RefValues, RefValues);
  EXPECT_EQ(m.mse, 0.0);
  EXPECT_EQ(m.relMse, 0.0);
  EXPECT_EQ(m.mae, 0.0);
  EXPECT_EQ(m.maxError, 0.0);
}

TEST(ImageMetrics, AccumulatorsMergedInPiecesEqualOneOverTheWhole) {
  ErrorAccumulator a, b;
  a.add(RefValues.data(), TestValues.data(), 1);
  b.add(RefValues.data() + 1, TestValues.data() + 1, 3);
  a.merge(b);
  ErrorMetrics merged = a.metrics(), whole = errorMetrics(RefValues, TestValues);
  EXPECT_DOUBLE_EQ(merged.mse, whole.mse);
  EXPECT_DOUBLE_EQ(merged.relMse, whole.relMse);
  EXPECT_DOUBLE_EQ(merged.mae, whole.mae);
  EXPECT_EQ(merged.maxError, whole.maxError);
  EXPECT_EQ(merged.count, whole.count);
}

TEST(ImageMetrics, NanInTheTestIsNotHidden) {
  std::vector<float> test = TestValues;
  test[1] = std::numeric_limits<float>::quiet_NaN();
  ErrorMetrics m = errorMetrics(RefValues, test);
  EXPECT_TRUE(std::isnan(m.mse));
  EXPECT_TRUE(std::isnan(m.maxError));
}

TEST(ImageMetrics, DifferentLengthsAreAnError) {
  std::vector<float> shorter(3, 0.0f);
  EXPECT_THROW(errorMetrics(RefValues, shorter), Error);
}

}  // namespace
}  // namespace femto
