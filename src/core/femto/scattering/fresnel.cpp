#include <femto/scattering/fresnel.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace femto {

float fresnelDielectric(float cosThetaI, float eta, float& cosThetaT) {
  // Relative index seen by the incident light: transmitted side over incident side.
  const bool outside = cosThetaI >= 0.0f;
  const float etaIT = outside ? eta : 1.0f / eta;
  const float etaTI = 1.0f / etaIT;
  const float cosI = std::min(std::abs(cosThetaI), 1.0f);
  // Snell's law: sin^2 T = (sin I / eta_it)^2.
  const float cos2T = 1.0f - etaTI * etaTI * (1.0f - cosI * cosI);
  if (cos2T <= 0.0f) {  // total internal reflection
    cosThetaT = 0.0f;
    return 1.0f;
  }
  const float cosT = std::sqrt(cos2T);
  // Amplitude ratios for s (perpendicular) and p (parallel) polarisation.
  const float rs = (cosI - etaIT * cosT) / (cosI + etaIT * cosT);
  const float rp = (etaIT * cosI - cosT) / (etaIT * cosI + cosT);
  cosThetaT = outside ? -cosT : cosT;
  return 0.5f * (rs * rs + rp * rp);
}

float fresnelDielectric(float cosThetaI, float eta) {
  float cosThetaT;
  return fresnelDielectric(cosThetaI, eta, cosThetaT);
}

Color3f fresnelConductor(float cosThetaI, const Color3f& eta, const Color3f& k) {
  const float c = std::clamp(cosThetaI, 0.0f, 1.0f);
  const float cos2 = c * c, sin2 = 1.0f - cos2;
  Color3f result;
  for (int i = 0; i < 3; ++i) {
    const float n2 = eta[i] * eta[i], k2 = k[i] * k[i];
    // a^2 + b^2 = |(eta + ik)^2 - sin^2|, and a = Re sqrt((eta + ik)^2 - sin^2).
    const float t0 = n2 - k2 - sin2;
    const float a2pb2 = std::sqrt(t0 * t0 + 4.0f * n2 * k2);
    const float a = std::sqrt(std::max(0.0f, 0.5f * (a2pb2 + t0)));
    const float t1 = a2pb2 + cos2, t2 = 2.0f * c * a;
    const float rs = (t1 - t2) / (t1 + t2);
    const float t3 = cos2 * a2pb2 + sin2 * sin2, t4 = t2 * sin2;
    const float rp = rs * (t3 - t4) / (t3 + t4);
    result[i] = 0.5f * (rs + rp);
  }
  return result;
}

Vec3f refract(const Vec3f& wi, float cosThetaT, float eta) {
  // Tangential components scale by 1/eta_it, the index ratio seen by wi.
  const float scale = wi.z >= 0.0f ? 1.0f / eta : eta;
  return {-scale * wi.x, -scale * wi.y, cosThetaT};
}

Vec3f refract(const Vec3f& wi, const Vec3f& m, float cosThetaT, float eta) {
  const float cosI = dot(wi, m);
  const float scale = cosI >= 0.0f ? 1.0f / eta : eta;
  return m * (cosI * scale + cosThetaT) - wi * scale;
}

float fresnelDiffuseReflectance(float eta) {
  if (eta < 1.0f) {
    // Egan & Hilgeman 1979 fit, accurate for the inverse of ordinary indices.
    return -1.4399f * eta * eta + 0.7099f * eta + 0.6681f + 0.0636f / eta;
  }
  // d'Eon & Irving 2011 quintic in 1/eta, accurate up to eta ~ 10.
  const float x = 1.0f / eta;
  return 0.919317f + x * (-3.4793f + x * (6.75335f + x * (-7.80989f + x * (4.98554f - 1.36881f * x))));
}

namespace {

struct ConductorEntry {
  std::string_view name;
  Color3f eta, k;
};

// Approximate RGB optical constants. Band reduction: each channel takes the
// tabulated spectral (n, k) near the centre of its band, 650 nm (R), 550 nm
// (G) and 450 nm (B), rounded to two or three digits; this is not a proper
// spectral-to-RGB projection, so colours are approximate (within a few
// percent in normal-incidence reflectance). Sources: Johnson & Christy 1972
// (Ag, Au, Cu), Rakic 1995 (Al), Palik, "Handbook of Optical Constants of
// Solids" (Cr, Hg, Mo, Ni, Pt, Rh, W). "none" is a perfect mirror.
constexpr std::array<ConductorEntry, 15> Conductors = {{
    {"none", {0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}},
    {"Ag", {0.15f, 0.12f, 0.14f}, {4.1f, 3.3f, 2.5f}},
    {"Al", {1.49f, 0.96f, 0.62f}, {7.8f, 6.69f, 5.47f}},
    {"Au", {0.17f, 0.42f, 1.42f}, {3.15f, 2.35f, 1.85f}},
    {"Cr", {3.2f, 3.1f, 2.4f}, {3.3f, 3.3f, 3.1f}},
    {"Cu", {0.21f, 0.96f, 1.17f}, {3.6f, 2.58f, 2.37f}},
    {"Cu_palik", {0.21f, 0.96f, 1.17f}, {3.6f, 2.58f, 2.37f}},
    {"Hg", {2.1f, 1.6f, 1.1f}, {5.2f, 4.6f, 3.9f}},
    {"Mo", {3.7f, 3.6f, 3.1f}, {3.6f, 3.5f, 3.3f}},
    {"Ni", {2.0f, 1.8f, 1.6f}, {3.8f, 3.3f, 2.9f}},
    {"Ni_palik", {2.0f, 1.8f, 1.6f}, {3.8f, 3.3f, 2.9f}},
    {"Pt", {2.4f, 2.1f, 1.8f}, {4.3f, 3.7f, 3.1f}},
    {"Rh", {2.1f, 1.8f, 1.6f}, {5.6f, 5.0f, 4.3f}},
    {"W", {3.7f, 3.5f, 3.3f}, {2.9f, 2.75f, 2.6f}},
    {"W_palik", {3.7f, 3.5f, 3.3f}, {2.9f, 2.75f, 2.6f}},
}};

}  // namespace

std::optional<std::pair<Color3f, Color3f>> lookupConductor(std::string_view name) {
  for (const auto& entry : Conductors)
    if (entry.name == name) return std::make_pair(entry.eta, entry.k);
  return std::nullopt;
}

std::vector<std::string> knownConductorNames() {
  std::vector<std::string> out;
  for (const auto& entry : Conductors) out.emplace_back(entry.name);
  return out;
}

}  // namespace femto
