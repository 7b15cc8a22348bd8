#pragma once
// Helpers for BSDF tests: interactions in the local frame, Monte Carlo
// albedo with its standard error, and the sample/eval/pdf consistency check.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include <femto/math/pcg32.h>
#include <femto/render/bsdf.h>

#include "chi2.h"
#include "plugin_util.h"

namespace femto::test {

/// An interaction whose shading frame is the local frame, seen from `wi`.
inline SurfaceInteraction localInteraction(const Vec3f& wi) {
  SurfaceInteraction si;
  si.n = Normal3f(0, 0, 1);
  si.wi = normalize(wi);
  return si;
}

/// A BSDF plugin built from `setup`'s parameters, as if written at scene.xml:3.
inline std::shared_ptr<BSDF> makeBSDF(const std::string& name, const std::function<void(Properties&)>& setup = {}) {
  Properties props(name);
  props.setLocation(SourceLocation{"scene.xml", 3});
  if (setup) setup(props);
  return createPlugin<BSDF>(ObjectKind::BSDF, props);
}

/// The Lambertian reflector of albedo `rho`.
inline std::shared_ptr<BSDF> makeDiffuse(const Color3f& rho) {
  return makeBSDF("diffuse", [&](Properties& p) { p.setColor("reflectance", rho); });
}

struct AlbedoEstimate {
  Color3f mean, standardError;
};

/// Albedo must not exceed `bound` beyond 5 standard errors and a float allowance.
inline void expectAlbedoAtMost(const AlbedoEstimate& e, float bound) {
  for (int c = 0; c < 3; ++c) EXPECT_LE(e.mean[c], bound + 5.0f * e.standardError[c] + 1e-5f) << "channel " << c;
}

inline void expectAlbedoNear(const AlbedoEstimate& e, const Color3f& expected, float relativeSlack = 0.0f) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(e.mean[c], expected[c], 5.0f * e.standardError[c] + relativeSlack * expected[c] + 1e-5f)
        << "channel " << c << ", standard error " << e.standardError[c];
}

/// Albedo rho(wi) = integral of f(wi, wo) |cos wo| dwo over the sphere,
/// estimated as the mean sample weight (failed samples count as zero).
inline AlbedoEstimate albedo(const BSDF& bsdf, const SurfaceInteraction& si, int n,
                             TransportMode mode = TransportMode::Radiance, uint64_t seed = 3) {
  PCG32 rng(seed, 11);
  double sum[3] = {0, 0, 0}, sumSq[3] = {0, 0, 0};
  for (int i = 0; i < n; ++i) {
    BSDFSample bs;
    Color3f w = bsdf.sample(si, rng.nextFloat(), {rng.nextFloat(), rng.nextFloat()}, bs, mode);
    if (!(bs.pdf > 0.0f)) w = Color3f(0.0f);
    for (int c = 0; c < 3; ++c) {
      sum[c] += w[c];
      sumSq[c] += double(w[c]) * w[c];
    }
  }
  AlbedoEstimate e;
  for (int c = 0; c < 3; ++c) {
    double mean = sum[c] / n, var = std::max(0.0, sumSq[c] / n - mean * mean);
    e.mean[c] = float(mean);
    e.standardError[c] = float(std::sqrt(var / (n - 1)));
  }
  return e;
}

/// For every sample of a smooth (non-delta) component: the density sample()
/// reports is pdf(wo), and the weight is eval(wo) / pdf(wo). Delta samples
/// must report a probability in (0, 1]. Returns the fraction of delta samples.
inline double checkSampleEvalPdf(const BSDF& bsdf, const SurfaceInteraction& si, int n,
                                 TransportMode mode = TransportMode::Radiance) {
  PCG32 rng(5, 13);
  int delta = 0;
  for (int i = 0; i < n; ++i) {
    BSDFSample bs;
    Color3f w = bsdf.sample(si, rng.nextFloat(), {rng.nextFloat(), rng.nextFloat()}, bs, mode);
    if (!(bs.pdf > 0.0f)) continue;
    EXPECT_TRUE(w.isValid()) << w;
    EXPECT_NEAR(length(bs.wo), 1.0f, 1e-4f);
    if (bs.sampledFlags & BSDFFlags::Delta) {
      ++delta;
      EXPECT_LE(bs.pdf, 1.0f);
      continue;
    }
    EXPECT_EQ(bs.sampledFlags & ~bsdf.flags(), 0u) << "sampled a component the BSDF does not declare";
    const float pdf = bsdf.pdf(si, bs.wo, mode);
    EXPECT_NEAR(bs.pdf, pdf, 1e-4f * pdf) << bs.wo;
    const Color3f f = bsdf.eval(si, bs.wo, mode);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(w[c], f[c] / pdf, 1e-4f * (f[c] / pdf) + 1e-6f) << bs.wo;
  }
  return double(delta) / n;
}

/// Chi-square test of the directions sample() draws from its smooth
/// components (delta samples are drawn again) against pdf(), normalised
/// over the sphere. Sets `smoothMass` to the integral of pdf(), the
/// probability of choosing a smooth component.
inline ChiSquareResult chiSquareSmoothLobes(const BSDF& bsdf, const SurfaceInteraction& si, double& smoothMass,
                                            TransportMode mode = TransportMode::Radiance) {
  GridDomain<Vec3f> domain = sphericalDomain(20, 40);
  std::function<double(const Vec3f&)> rawPdf = [&](const Vec3f& wo) { return double(bsdf.pdf(si, wo, mode)); };
  smoothMass = 0.0;
  for (double cell : integrateCells(domain, rawPdf, 8)) smoothMass += cell;
  PCG32 rng(9, 17);
  std::function<Vec3f(const Point2f&)> sample = [&](const Point2f& u) {
    Point2f v = u;
    for (int attempt = 0; attempt < 1000; ++attempt) {
      BSDFSample bs;
      bsdf.sample(si, rng.nextFloat(), v, bs, mode);
      if (bs.pdf > 0.0f && !(bs.sampledFlags & BSDFFlags::Delta)) return bs.wo;
      v = Point2f(rng.nextFloat(), rng.nextFloat());
    }
    return Vec3f(0.0f);  // fails the test: not a unit vector
  };
  const double mass = smoothMass;
  std::function<double(const Vec3f&)> pdf = [&, mass](const Vec3f& wo) { return rawPdf(wo) / mass; };
  return testSampler<Vec3f>(domain, sample, pdf, 300000, 8);
}

}  // namespace femto::test
