// Warps from the unit square (see warp.h). Every density is with respect to
// the measure of the target domain (area for the disk, solid angle for
// directions); tests/unit/math/test_warp.cpp checks each pair with a chi-square test.
#include <femto/math/warp.h>

#include <femto/math/constants.h>

namespace femto::warp {

Point2f squareToUniformDiskConcentric(const Point2f& u) {
  // Shirley and Chiu 1997, "A Low Distortion Map Between Disk and Square":
  // concentric squares map to concentric circles, so strata stay compact.
  float a = 2.0f * u.x - 1.0f, b = 2.0f * u.y - 1.0f;
  if (a == 0.0f && b == 0.0f) return {0.0f, 0.0f};
  float r, phi;
  if (a * a > b * b) {
    r = a;
    phi = (Pi / 4.0f) * (b / a);
  } else {
    r = b;
    phi = (Pi / 2.0f) - (Pi / 4.0f) * (a / b);
  }
  return {r * std::cos(phi), r * std::sin(phi)};
}

float squareToUniformDiskPdf(const Point2f& p) { return p.x * p.x + p.y * p.y <= 1.0f ? InvPi : 0.0f; }

Vec3f squareToUniformSphere(const Point2f& u) {
  // z uniform in [-1, 1] gives uniform area (Archimedes' hat-box theorem).
  float z = 1.0f - 2.0f * u.x;
  float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  float phi = 2.0f * Pi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

float squareToUniformSpherePdf(const Vec3f&) { return Inv4Pi; }

Vec3f squareToUniformHemisphere(const Point2f& u) {
  // z in (0, 1]: never exactly grazing, where the direction would be useless.
  float z = 1.0f - u.x;
  float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  float phi = 2.0f * Pi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

float squareToUniformHemispherePdf(const Vec3f& v) { return v.z >= 0.0f ? Inv2Pi : 0.0f; }

Vec3f squareToCosineHemisphere(const Point2f& u) {
  // Malley's method: project a uniform disk sample up onto the hemisphere.
  Point2f d = squareToUniformDiskConcentric(u);
  float z = std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
  return {d.x, d.y, z};
}

float squareToCosineHemispherePdf(const Vec3f& v) { return v.z > 0.0f ? v.z * InvPi : 0.0f; }

Vec3f squareToUniformCone(const Point2f& u, float cosCutoff) {
  // cos(theta) uniform in [cosCutoff, 1] is uniform in solid angle.
  float z = 1.0f - u.x * (1.0f - cosCutoff);
  float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  float phi = 2.0f * Pi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

float squareToUniformConePdf(const Vec3f& v, float cosCutoff) {
  return v.z >= cosCutoff ? 1.0f / (2.0f * Pi * (1.0f - cosCutoff)) : 0.0f;
}

Point2f squareToUniformTriangle(const Point2f& u) {
  // Reflect the upper-right half of the square onto the lower-left one: it is
  // measure preserving, unlike the sqrt map, and keeps stratification.
  if (u.x + u.y > 1.0f) return {1.0f - u.x, 1.0f - u.y};
  return u;
}

}  // namespace femto::warp
