#include <femto/transport/point_directions.h>

#include <cmath>

#include <femto/math/constants.h>
#include <femto/math/frame.h>

namespace femto {
namespace {

/// 1 / (pi^2 sin alpha), 0 outside the hemisphere facing c. sin alpha comes
/// from a cross product, not from cos alpha: accurate at the small angles
/// where the density matters (MIS weights of rays passing close to c).
float densityOf(double cosAlpha, double sinAlpha) {
  if (!(cosAlpha > 0.0) || !(sinAlpha > 0.0)) return 0.0f;
  return float(1.0 / (double(Pi) * double(Pi) * sinAlpha));
}

}  // namespace

Vec3f samplePointDirection(const Point3f& y, const Point3f& c, const Point2f& u, float& pdf) {
  pdf = 0.0f;
  Vec3f toC = c - y;
  float dist = length(toC);
  if (!(dist > 0.0f)) return Vec3f(0.0f);
  double alpha = 0.5 * double(Pi) * double(u.x), phi = 2.0 * double(Pi) * double(u.y);
  double sinAlpha = std::sin(alpha), cosAlpha = std::cos(alpha);
  Frame frame(toC / dist);
  Vec3f w = normalize(frame.toWorld(Vec3f(float(sinAlpha * std::cos(phi)), float(sinAlpha * std::sin(phi)), float(cosAlpha))));
  pdf = densityOf(cosAlpha, sinAlpha);
  return w;
}

float pdfPointDirection(const Point3f& y, const Point3f& c, const Vec3f& w) {
  Vec3f toC = c - y;
  float dist = length(toC);
  if (!(dist > 0.0f)) return 0.0f;
  return densityOf(double(dot(w, toC)) / double(dist), double(length(cross(w, toC))) / double(dist));
}

}  // namespace femto
