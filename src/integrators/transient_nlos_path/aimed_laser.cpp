#include "aimed_laser.h"

#include <cmath>

#include <femto/lights/oriented_point_emitter.h>

namespace femto {
namespace {

/// An orthonormal frame from a transform's axes (Gram-Schmidt from +z, then
/// +y), so scaled or sheared to_world transforms still give a rotation.
Frame frameOf(const Transform& toWorld) {
  Vec3f z = normalize(toWorld.vector(Vec3f(0, 0, 1)));
  Vec3f y = toWorld.vector(Vec3f(0, 1, 0));
  y = normalize(y - z * dot(y, z));
  return Frame(cross(y, z), y, z);
}

/// Mitsuba's look-at frame: forward toward the target, up = +y unless the
/// laser points (nearly) along it.
Frame lookAtFrame(const Vec3f& forward) {
  Vec3f up = std::abs(forward.y) > 0.999f ? Vec3f(0, 0, 1) : Vec3f(0, 1, 0);
  Vec3f left = normalize(cross(up, forward));
  return Frame(left, cross(forward, left), forward);
}

}  // namespace

AimedLaser::AimedLaser(const Emitter& emitter, const std::optional<Point3f>& origin, const Point3f& target)
    : emitter_(&emitter) {
  Point3f position(0.0f);
  emitter.deltaPosition(position);
  position_ = position;
  origin_ = origin ? *origin : position;
  if (auto* oriented = dynamic_cast<const OrientedPointEmitter*>(&emitter)) {
    own_ = frameOf(oriented->toWorld());
    Vec3f forward = target - origin_;
    float len = length(forward);
    aimed_ = len > 0.0f ? lookAtFrame(forward / len) : own_;
  }
}

AimedLaser::AimedLaser(const Emitter& emitter) : emitter_(&emitter) {
  Point3f position(0.0f);
  emitter.deltaPosition(position);
  position_ = origin_ = position;
  if (auto* oriented = dynamic_cast<const OrientedPointEmitter*>(&emitter)) aimed_ = own_ = frameOf(oriented->toWorld());
}

Color3f AimedLaser::incident(const Point3f& ref, DirectionSample& ds) const {
  Point3f turned = position_ + own_.toWorld(aimed_.toLocal(ref - origin_));
  DirectionSample own;
  Color3f value = emitter_->sampleDirection(turned, Point2f(0.5f), own);
  if (!(own.pdf > 0.0f)) return Color3f(0.0f);
  ds = own;
  ds.p = origin_;
  ds.d = aimed_.toWorld(own_.toLocal(own.d));
  ds.emitter = emitter_;
  return value;
}

Color3f AimedLaser::sampleRay(const Point2f& uPosition, const Point2f& uDirection, Ray& ray) const {
  Ray own;
  Color3f weight = emitter_->sampleRay(uPosition, uDirection, own);
  ray = Ray(origin_, normalize(aimed_.toWorld(own_.toLocal(own.d))));
  return weight;
}

}  // namespace femto
