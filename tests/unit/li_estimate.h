#pragma once
// Estimating an integrator's Li with error bars, for accuracy tests that
// compare with closed forms: the tolerance comes from the estimator's own
// standard error, measured from the samples.
#include <initializer_list>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

#include <femto/math/pcg32.h>
#include <femto/math/warp.h>
#include <femto/render/integrator.h>
#include <femto/render/sampler.h>
#include <femto/render/scene.h>
#include <femto/xml/loader.h>

namespace femto::test {

/// "r, g, b" for an <rgb value="..."/> attribute.
inline std::string rgb(const Color3f& c) { return str(c.r, ", ", c.g, ", ", c.b); }

/// A scene from XML text, loaded in strict mode (unused parameters are errors).
inline std::shared_ptr<Scene> loadStrict(const std::string& xml) {
  LoadOptions options;
  options.strict = true;
  return loadSceneFromString(xml, std::filesystem::temp_directory_path(), options, "<accuracy test>");
}

struct Estimate {
  Color3f mean, standardError;
};

/// Sample mean and its standard error, per channel, from running sums.
class MeanAccumulator {
 public:
  void add(const Color3f& v) {
    ++n_;
    for (int c = 0; c < 3; ++c) {
      sum_[c] += v[c];
      sumSq_[c] += double(v[c]) * v[c];
    }
  }
  Estimate estimate() const {
    Estimate e;
    for (int c = 0; c < 3; ++c) {
      double mean = sum_[c] / n_;
      double variance = std::max(0.0, (sumSq_[c] / n_ - mean * mean) * n_ / (n_ - 1));
      e.mean[c] = float(mean);
      e.standardError[c] = float(std::sqrt(variance / n_));
    }
    return e;
  }

 private:
  long n_ = 0;
  double sum_[3] = {0, 0, 0}, sumSq_[3] = {0, 0, 0};
};

/// Mean and standard error of Li over `n` independent rays from `makeRay`.
template <typename RayFn>
Estimate estimateLi(const Scene& scene, int n, RayFn&& makeRay) {
  auto integrator = dynamic_cast<const SamplingIntegrator*>(&scene.integrator());
  EXPECT_NE(integrator, nullptr);
  std::unique_ptr<Sampler> sampler = scene.sensor().sampler().clone();
  PCG32 rng(17, 23);
  MeanAccumulator acc;
  for (int i = 0; i < n; ++i) {
    sampler->startPixel(5, uint64_t(i));
    Color3f L = integrator->Li(makeRay(rng), scene, *sampler);
    EXPECT_TRUE(L.isValid()) << L;
    acc.add(L);
  }
  return acc.estimate();
}

inline void expectWithinErrorBars(const Estimate& e, const Color3f& expected) {
  for (int c = 0; c < 3; ++c) {
    // 5 sigma, plus 2e-4 relative for zero- or near-zero-variance estimators:
    // the core offsets spawned rays by RayEpsilon = 1e-4 (relative to scene
    // scale), which perturbs the geometry, and so the estimate, at that level.
    float tolerance = 5.0f * e.standardError[c] + 2e-4f * expected[c];
    EXPECT_NEAR(e.mean[c], expected[c], tolerance)
        << "channel " << c << ": standard error " << e.standardError[c];
  }
}

/// Direct lighting from a large sphere light (radius 1, centre (0, 0, 2),
/// black, radiance Le) over the diffuse plane z = 0 of reflectance `rho`,
/// rendered by `integratorXml`. Seen from a plane point x with the sphere
/// wholly above its horizon, the sphere's form factor gives
/// E = pi Le (R / |c - x|)^2 cos(theta), so L = rho / pi * E. The sphere covers
/// a large solid angle, so emitter and BSDF sampling both contribute and
/// their MIS weights must sum to one.
inline void expectSphereLightFormFactor(const std::string& integratorXml, const Color3f& rho,
                                        std::initializer_list<Point3f> points) {
  const float R = 1.0f;
  const Point3f c(0, 0, 2);
  const Color3f Le(2.0f, 1.0f, 0.5f);
  auto scene = loadStrict(str(R"(<scene version="3.0.0">)", integratorXml, R"(
  <shape type="rectangle">
    <transform name="to_world"><scale value="20"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value=")", rgb(rho), R"("/></bsdf>
  </shape>
  <shape type="sphere">
    <point name="center" x=")", c.x, R"(" y=")", c.y, R"(" z=")", c.z, R"("/>
    <float name="radius" value=")", R, R"("/>
    <bsdf type="diffuse"><rgb name="reflectance" value="0"/></bsdf>
    <emitter type="area"><rgb name="radiance" value=")", rgb(Le), R"("/></emitter>
  </shape>
</scene>)"));
  const Point3f eye(3.0f, -2.0f, 0.5f);
  for (Point3f x : points) {
    SCOPED_TRACE(str("point ", x));
    float d = distance(c, x);
    Color3f expected = rho * Le * (R * R / (d * d) * ((c.z - x.z) / d));
    expectWithinErrorBars(estimateLi(*scene, 20000, [&](PCG32&) { return Ray(eye, normalize(x - eye)); }), expected);
  }
}

/// Rays from random points well inside the unit sphere in uniform directions:
/// in the furnace the radiance is the same everywhere.
inline Ray randomInteriorRay(PCG32& rng) {
  Point3f o = warp::squareToUniformSphere({rng.nextFloat(), rng.nextFloat()}) * (0.5f * rng.nextFloat());
  return Ray(o, warp::squareToUniformSphere({rng.nextFloat(), rng.nextFloat()}));
}

}  // namespace femto::test
