#include <femto/scattering/microfacet.h>

#include <algorithm>
#include <cmath>

#include <femto/core/properties.h>
#include <femto/math/constants.h>

namespace femto {
namespace {

constexpr float MinAlpha = 1e-4f;
constexpr double SqrtPi = 1.77245385090551602730;

/// Largest float below 1: keeps the radial warps of sampleAll finite.
constexpr float OneMinusEpsilon = 0x1.fffffep-1f;

/// Inverse error function, M. Giles, "Approximating the erfinv function"
/// (GPU Computing Gems, 2010), single-precision polynomials: a starting
/// point for Newton's method, accurate to a few float ulps.
double erfinvApprox(double x) {
  double w = -std::log((1.0 - x) * (1.0 + x)), p;
  if (w < 5.0) {
    w -= 2.5;
    p = 2.81022636e-08;
    for (double c : {3.43273939e-07, -3.5233877e-06, -4.39150654e-06, 0.00021858087, -0.00125372503, -0.00417768164,
                     0.246640727, 1.50140941})
      p = c + p * w;
  } else {
    w = std::sqrt(w) - 3.0;
    p = -0.000200214257;
    for (double c : {0.000100950558, 0.00134934322, -0.00367342844, 0.00573950773, -0.0076224613, 0.00943887047,
                     1.00167406, 2.83297682})
      p = c + p * w;
  }
  return p * x;
}

/// Solve cdf(x) = target for a non-decreasing cdf on [lo, hi], from `x`, by
/// Newton steps safeguarded with bisection (a Newton step leaving the bracket
/// is replaced by the bracket's midpoint), so it converges even where the
/// density is nearly zero.
template <typename Cdf, typename Pdf>
double invertCdf(const Cdf& cdf, const Pdf& pdf, double target, double lo, double hi, double x) {
  x = std::clamp(x, lo, hi);
  for (int iteration = 0; iteration < 64; ++iteration) {
    double value = cdf(x) - target;
    if (value > 0.0) hi = x; else lo = x;
    double density = pdf(x);
    double step = density > 0.0 ? value / density : Infinity;
    if (std::abs(step) < 1e-9) return x - step;  // converged (also when x is exact)
    double next = x - step;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo < 1e-9) return next;
    x = next;
  }
  return x;
}

/// The microfacet normal with slopes (x, y): m = (-x, -y, 1) / |.|.
Vec3f normalFromSlopes(float x, float y) { return normalize(Vec3f(-x, -y, 1.0f)); }

}  // namespace

const char* microfacetTypeName(MicrofacetType type) {
  return type == MicrofacetType::GGX ? "ggx" : "beckmann";
}

MicrofacetDistribution::MicrofacetDistribution(MicrofacetType type, float alphaU, float alphaV, bool sampleVisible)
    : type_(type), alphaU_(std::max(alphaU, MinAlpha)), alphaV_(std::max(alphaV, MinAlpha)),
      sampleVisible_(sampleVisible) {}

MicrofacetDistribution MicrofacetDistribution::fromProperties(const Properties& props, bool allowAnisotropic) {
  const MicrofacetType type = props.getEnum(
      "distribution", MicrofacetType::Beckmann, {{"beckmann", MicrofacetType::Beckmann}, {"ggx", MicrofacetType::GGX}});

  auto readAlpha = [&](const std::string& key) { return props.getFloat(key, 0.1f, Range::nonNegative(), "a roughness"); };
  float alphaU = 0.1f, alphaV = 0.1f;
  bool anisotropic = allowAnisotropic && (props.has("alpha_u") || props.has("alpha_v"));
  if (anisotropic) {
    if (props.has("alpha"))
      props.raise("alpha", "give either \"alpha\" (isotropic) or \"alpha_u\" and \"alpha_v\" (anisotropic), not both");
    for (const char* key : {"alpha_u", "alpha_v"})
      if (!props.has(key))
        props.raise(key, str("an anisotropic roughness needs both \"alpha_u\" and \"alpha_v\"; \"", key,
                             "\" is missing"));
    alphaU = readAlpha("alpha_u");
    alphaV = readAlpha("alpha_v");
  } else {
    alphaU = alphaV = readAlpha("alpha");
  }
  return MicrofacetDistribution(type, alphaU, alphaV, props.getBool("sample_visible", true));
}

float MicrofacetDistribution::projectedRoughness2(const Vec3f& w) const {
  return alphaU_ * alphaU_ * w.x * w.x + alphaV_ * alphaV_ * w.y * w.y;
}

float MicrofacetDistribution::D(const Vec3f& m) const {
  if (m.z <= 0.0f) return 0.0f;
  // Squared slopes of m in the space where the roughness is 1.
  float sx = m.x / alphaU_, sy = m.y / alphaV_;
  float cos2 = m.z * m.z;
  if (type_ == MicrofacetType::GGX) {
    // 1 / (pi au av cos^4 (1 + tan^2 (cos^2 phi / au^2 + sin^2 phi / av^2))^2), multiplied out.
    float e = sx * sx + sy * sy + cos2;
    return 1.0f / (Pi * alphaU_ * alphaV_ * e * e);
  }
  float result = std::exp(-(sx * sx + sy * sy) / cos2) / (Pi * alphaU_ * alphaV_ * cos2 * cos2);
  return std::isfinite(result) ? result : 0.0f;  // grazing m: exp underflows while cos^4 -> 0
}

float MicrofacetDistribution::lambda(const Vec3f& w) const {
  // alpha^2 tan^2(theta) of w, with alpha the projected roughness.
  float a2t2 = projectedRoughness2(w) / (w.z * w.z);
  if (!(a2t2 > 0.0f)) return w.z == 0.0f ? Infinity : 0.0f;
  if (!std::isfinite(a2t2)) return Infinity;
  if (type_ == MicrofacetType::GGX)  // (sqrt(1 + a2t2) - 1) / 2, without cancellation for small a2t2
    return a2t2 / (2.0f * (std::sqrt(1.0f + a2t2) + 1.0f));
  // Beckmann, a = 1 / (alpha tan): Lambda = (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)).
  double a = 1.0 / std::sqrt(double(a2t2));
  return float(0.5 * (std::exp(-a * a) / (a * SqrtPi) - std::erfc(a)));
}

float MicrofacetDistribution::G1(const Vec3f& w, const Vec3f& m) const {
  if (dot(w, m) * w.z <= 0.0f) return 0.0f;
  return 1.0f / (1.0f + lambda(w));
}

float MicrofacetDistribution::G(const Vec3f& wi, const Vec3f& wo, const Vec3f& m) const {
  return G1(wi, m) * G1(wo, m);
}

Vec3f MicrofacetDistribution::sample(const Vec3f& wi, const Point2f& u) const {
  if (!sampleVisible_) return sampleAll(u);
  Vec3f w = wi.z < 0.0f ? -wi : wi;
  return type_ == MicrofacetType::GGX ? sampleVisibleGGX(w, u) : sampleVisibleBeckmann(w, u);
}

float MicrofacetDistribution::pdf(const Vec3f& wi, const Vec3f& m) const {
  if (m.z <= 0.0f) return 0.0f;
  if (!sampleVisible_) return D(m) * m.z;
  Vec3f w = wi.z < 0.0f ? -wi : wi;
  if (w.z <= 0.0f) return 0.0f;
  // D_wi(m) (Heitz 2014, eq. 38).
  return G1(w, m) * std::max(0.0f, dot(w, m)) * D(m) / w.z;
}

float MicrofacetDistribution::sampleWeight(const Vec3f& wi, const Vec3f& wo, const Vec3f& m) const {
  float g1i = G1(wi, m);
  if (g1i <= 0.0f || m.z <= 0.0f) return 0.0f;
  if (sampleVisible_) return G1(wo, m);
  return g1i * G1(wo, m) * std::abs(dot(wi, m)) / (std::abs(wi.z) * m.z);
}

Vec3f MicrofacetDistribution::sampleAll(const Point2f& u) const {
  // Slopes of the roughness-1 distribution are radially symmetric: the radial
  // CDF is r^2 / (1 + r^2) for GGX and 1 - exp(-r^2) for Beckmann. Scaling the
  // slopes by (alpha_u, alpha_v) gives the anisotropic distribution, and
  // sampling slopes by P22 samples normals by D(m) cos(theta_m) (Walter eqs.
  // 28, 35 are the isotropic special case).
  float u1 = std::min(u.x, OneMinusEpsilon);
  float r = type_ == MicrofacetType::GGX ? std::sqrt(u1 / (1.0f - u1)) : std::sqrt(-std::log1p(-u1));
  float phi = 2.0f * Pi * u.y;
  return normalFromSlopes(alphaU_ * r * std::cos(phi), alphaV_ * r * std::sin(phi));
}

Vec3f MicrofacetDistribution::sampleVisibleGGX(const Vec3f& wi, const Point2f& u) const {
  // Heitz 2018, listing 1: in the space where the roughness is 1 the visible
  // GGX normals are the projection of a uniformly sampled disk onto the
  // hemisphere facing the stretched wi; the half of the disk the hemisphere
  // hides from wi is folded over by the warp of t2.
  Vec3f vh = normalize(Vec3f(alphaU_ * wi.x, alphaV_ * wi.y, wi.z));
  float lensq = vh.x * vh.x + vh.y * vh.y;
  Vec3f t1 = lensq > 0.0f ? Vec3f(-vh.y, vh.x, 0.0f) / std::sqrt(lensq) : Vec3f(1.0f, 0.0f, 0.0f);
  Vec3f t2 = cross(vh, t1);
  float r = std::sqrt(u.x), phi = 2.0f * Pi * u.y;
  float p1 = r * std::cos(phi), p2 = r * std::sin(phi);
  float s = 0.5f * (1.0f + vh.z);
  p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * p2;
  Vec3f nh = t1 * p1 + t2 * p2 + vh * std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2));
  // Unstretch; the normal of the roughness-1 surface maps to (au x, av y, z).
  Vec3f m = normalize(Vec3f(alphaU_ * nh.x, alphaV_ * nh.y, std::max(1e-7f, nh.z)));
  return m;
}

Vec3f MicrofacetDistribution::sampleVisibleBeckmann(const Vec3f& wi, const Point2f& u) const {
  // Heitz & d'Eon 2014, section 4: stretch wi to roughness 1, sample the
  // visible slopes there for the incident angle theta (wi in the xz-plane),
  // rotate them to wi's azimuth and unstretch. For roughness 1 the slope
  // density of visible normals is (cos - x sin) exp(-x^2 - y^2) / pi for x <
  // cot(theta): x has the CDF C(x) = cos (1 + erf x) / 2 + sin exp(-x^2) /
  // (2 sqrt(pi)), whose total C(cot) = cos (1 + Lambda), and y given x is the
  // normal distribution of variance 1/2. Both CDFs are inverted numerically
  // (Newton with bisection, in double precision).
  Vec3f ws = normalize(Vec3f(alphaU_ * wi.x, alphaV_ * wi.y, wi.z));
  double cosTheta = std::max(0.0f, ws.z);
  double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  double sinPhiLen = std::sqrt(double(ws.x) * ws.x + double(ws.y) * ws.y);
  double cosPhi = sinPhiLen > 0.0 ? ws.x / sinPhiLen : 1.0, sinPhi = sinPhiLen > 0.0 ? ws.y / sinPhiLen : 0.0;

  // Beyond |slope| = 8 the Gaussian holds less than 1e-28 of the mass.
  constexpr double Limit = 8.0;
  double cotTheta = sinTheta > 0.0 ? cosTheta / sinTheta : Limit;
  auto cdfX = [&](double x) { return 0.5 * cosTheta * std::erfc(-x) + 0.5 * sinTheta * std::exp(-x * x) / SqrtPi; };
  auto pdfX = [&](double x) { return std::max(0.0, cosTheta - x * sinTheta) * std::exp(-x * x) / SqrtPi; };
  double hi = std::min(cotTheta, Limit);
  double target = u.x * cdfX(hi);
  // Start x where the Gaussian part of C alone reaches the target: exact at
  // normal incidence, close while cos(theta) dominates.
  double guess = cosTheta > 0.0 ? erfinvApprox(std::clamp(2.0 * target / cosTheta - 1.0, -0.999999, 0.999999)) : 0.0;
  double x = invertCdf(cdfX, pdfX, target, -Limit, hi, guess);
  auto cdfY = [](double y) { return 0.5 * std::erfc(-y); };
  auto pdfY = [](double y) { return std::exp(-y * y) / SqrtPi; };
  double uy = std::clamp(double(u.y), 1e-12, 1.0 - 1e-12);
  double y = invertCdf(cdfY, pdfY, uy, -Limit, Limit, erfinvApprox(2.0 * uy - 1.0));

  float slopeX = float(cosPhi * x - sinPhi * y), slopeY = float(sinPhi * x + cosPhi * y);
  return normalFromSlopes(alphaU_ * slopeX, alphaV_ * slopeY);
}

std::string MicrofacetDistribution::toString() const {
  return str("MicrofacetDistribution[type=", microfacetTypeName(type_), ", alpha_u=", alphaU_, ", alpha_v=", alphaV_,
             ", sample_visible=", sampleVisible_ ? "true" : "false", "]");
}

}  // namespace femto
