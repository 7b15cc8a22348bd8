// ImageBlock: filter footprints and weights, refusal of invalid values, merging.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <femto/render/image_block.h>
#include <femto/render/rfilter.h>

#include "render_test_util.h"

namespace femto {
namespace {

std::shared_ptr<ReconstructionFilter> tent(float radius) {
  Properties props("tent");
  props.setFloat("radius", radius);
  return test::makePlugin<ReconstructionFilter>(ObjectKind::ReconstructionFilter, props);
}

/// Weight stored for film pixel (x, y).
float weightAt(const ImageBlock& b, int x, int y) {
  return b.pixel(x - b.offset().x + b.border(), y - b.offset().y + b.border())[3];
}

TEST(ImageBlock, BoxOfHalfPixelPutsEachSampleInTheContainingPixel) {
  ImageBlock block({2, 3}, {4, 4}, nullptr);
  EXPECT_EQ(block.border(), 0);
  ASSERT_TRUE(block.put({3.2f, 4.7f}, Color3f(1, 2, 3)));
  ASSERT_TRUE(block.put({4.0f, 3.0f}, Color3f(5)));  // exactly on a corner: pixel (4, 3)
  float total = 0;
  for (int y = 3; y < 7; ++y)
    for (int x = 2; x < 6; ++x) total += weightAt(block, x, y);
  EXPECT_EQ(total, 2.0f);
  EXPECT_EQ(weightAt(block, 3, 4), 1.0f);
  EXPECT_EQ(weightAt(block, 4, 3), 1.0f);
  EXPECT_EQ(block.value({3, 4}), Color3f(1, 2, 3));
  EXPECT_EQ(block.value({2, 3}), Color3f(0));  // no samples: black, not NaN
}

TEST(ImageBlock, TentWeightsFollowTheFilterProfile) {
  auto filter = tent(1.0f);
  ImageBlock block({0, 0}, {10, 10}, filter.get());
  EXPECT_EQ(block.border(), 1);
  // Distances to the pixel centres 5.5 and 6.5 are 1/4 and 3/4 (table nodes,
  // so the tabulated weights are exact): weights 3/4 and 1/4 along x, 1 along y.
  ASSERT_TRUE(block.put({5.75f, 5.5f}, Color3f(2)));
  EXPECT_FLOAT_EQ(weightAt(block, 5, 5), 0.75f);
  EXPECT_FLOAT_EQ(weightAt(block, 6, 5), 0.25f);
  EXPECT_FLOAT_EQ(weightAt(block, 4, 5), 0.0f);
  EXPECT_FLOAT_EQ(weightAt(block, 5, 4), 0.0f);
  EXPECT_FLOAT_EQ(block.pixel(5 + 1, 5 + 1)[0], 2.0f * 0.75f);
  EXPECT_EQ(block.value({6, 5}), Color3f(2));
}

TEST(ImageBlock, ValueIsTheWeightedMeanOfOverlappingSamples) {
  auto filter = tent(1.0f);
  ImageBlock block({0, 0}, {4, 4}, filter.get());
  ASSERT_TRUE(block.put({1.5f, 1.5f}, Color3f(1)));     // weight 1 at pixel (1, 1)
  ASSERT_TRUE(block.put({1.75f, 1.5f}, Color3f(3)));    // weight 3/4 there
  Color3f v = block.value({1, 1});
  EXPECT_NEAR(v.r, (1.0f * 1.0f + 3.0f * 0.75f) / 1.75f, 1e-6f);
}

TEST(ImageBlock, BorderCatchesSamplesNearTheEdge) {
  auto filter = tent(2.0f);
  ImageBlock block({10, 10}, {2, 2}, filter.get());
  EXPECT_EQ(block.border(), 2);  // ceil(2 - 1/2)
  ASSERT_TRUE(block.put({10.0f, 10.0f}, Color3f(1)));
  // Pixel 8 has its centre 1.5 from the sample: inside the radius, stored in the border.
  EXPECT_GT(weightAt(block, 8, 8), 0.0f);
  EXPECT_GT(weightAt(block, 11, 11), 0.0f);
}

TEST(ImageBlock, RefusesNaNInfinityAndNegativeValues) {
  ImageBlock block({0, 0}, {2, 2}, nullptr);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  EXPECT_FALSE(block.put({0.5f, 0.5f}, Color3f(nan, 0, 0)));
  EXPECT_FALSE(block.put({0.5f, 0.5f}, Color3f(0, inf, 0)));
  EXPECT_FALSE(block.put({0.5f, 0.5f}, Color3f(0, 0, -1e-3f)));
  EXPECT_EQ(weightAt(block, 0, 0), 0.0f);
  EXPECT_TRUE(block.put({0.5f, 0.5f}, Color3f(0)));  // black is a valid sample
  EXPECT_EQ(weightAt(block, 0, 0), 1.0f);
}

TEST(ImageBlock, MergeAddsOverlappingSums) {
  auto filter = tent(1.0f);
  ImageBlock full({0, 0}, {8, 8}, filter.get());
  ImageBlock left({0, 0}, {4, 8}, filter.get()), right({4, 0}, {4, 8}, filter.get());
  ImageBlock reference({0, 0}, {8, 8}, filter.get());
  // Samples near the seam spill into the other tile's border.
  const Point2f positions[] = {{3.9f, 2.2f}, {4.1f, 2.2f}, {0.3f, 7.9f}, {7.7f, 0.1f}};
  for (const Point2f& p : positions) {
    (p.x < 4 ? left : right).put(p, Color3f(p.x, p.y, 1));
    reference.put(p, Color3f(p.x, p.y, 1));
  }
  full.merge(left);
  full.merge(right);
  for (int y = 0; y < full.storedHeight(); ++y)
    for (int x = 0; x < full.storedWidth(); ++x)
      for (int c = 0; c < 4; ++c) EXPECT_NEAR(full.pixel(x, y)[c], reference.pixel(x, y)[c], 1e-6f);
}

TEST(ReconstructionFilter, GaussianHasMitsubaRadiusAndReachesZero) {
  Properties props("gaussian");
  auto g = test::makePlugin<ReconstructionFilter>(ObjectKind::ReconstructionFilter, props);
  EXPECT_FLOAT_EQ(g->radius(), 2.0f);  // 4 * stddev 0.5
  EXPECT_FLOAT_EQ(g->evalTabulated(0.0f), 1.0f - std::exp(-8.0f));
  EXPECT_EQ(g->evalTabulated(2.0f), 0.0f);
  EXPECT_EQ(g->evalTabulated(2.5f), 0.0f);
  EXPECT_NEAR(g->evalTabulated(0.5f), std::exp(-0.5f) - std::exp(-8.0f), 1e-6f);
}

}  // namespace
}  // namespace femto
