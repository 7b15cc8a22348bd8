#pragma once
// Warps from the unit square to common domains, with their densities.
// Each pair (squareToX, squareToXPdf) is checked by a chi-square test.
#include <femto/math/vector.h>

namespace femto::warp {

/// Uniform on the unit disk, Shirley-Chiu concentric mapping (low distortion).
Point2f squareToUniformDiskConcentric(const Point2f& u);
float squareToUniformDiskPdf(const Point2f& p);
/// Uniform on the unit sphere.
Vec3f squareToUniformSphere(const Point2f& u);
float squareToUniformSpherePdf(const Vec3f& v);
/// Uniform on the upper (+z) hemisphere.
Vec3f squareToUniformHemisphere(const Point2f& u);
float squareToUniformHemispherePdf(const Vec3f& v);
/// Cosine-weighted on the upper hemisphere (Malley's method).
Vec3f squareToCosineHemisphere(const Point2f& u);
float squareToCosineHemispherePdf(const Vec3f& v);
/// Uniform in the cone around +z with cos(half-angle) = cosCutoff.
Vec3f squareToUniformCone(const Point2f& u, float cosCutoff);
float squareToUniformConePdf(const Vec3f& v, float cosCutoff);
/// Uniform barycentrics (b1, b2) on a triangle; b0 = 1 - b1 - b2.
Point2f squareToUniformTriangle(const Point2f& u);

}  // namespace femto::warp
