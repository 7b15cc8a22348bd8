// Embree 3 scene: the only file of femto that includes Embree.
#include <femto/render/detail/embree_accel.h>

#include <embree3/rtcore.h>

#include <femto/core/log.h>
#include <femto/render/mesh.h>
#include <femto/render/shape.h>

namespace femto::detail {
namespace {

void deviceError(void*, RTCError code, const char* message) {
  logError("Embree error ", int(code), ": ", message ? message : "(no message)");
}

// --- user geometry callbacks for analytic shapes (one primitive per shape) ---

void userBounds(const RTCBoundsFunctionArguments* args) {
  const auto* shape = static_cast<const Shape*>(args->geometryUserPtr);
  BoundingBox3f b = shape->bbox();
  *args->bounds_o = RTCBounds{b.min.x, b.min.y, b.min.z, 0.0f, b.max.x, b.max.y, b.max.z, 0.0f};
}

void userIntersect(const RTCIntersectFunctionNArguments* args) {
  if (args->N != 1 || !args->valid[0]) return;  // rtcIntersect1 only
  auto* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
  const auto* shape = static_cast<const Shape*>(args->geometryUserPtr);
  Ray ray(Point3f(rh->ray.org_x, rh->ray.org_y, rh->ray.org_z), Vec3f(rh->ray.dir_x, rh->ray.dir_y, rh->ray.dir_z),
          rh->ray.tnear, rh->ray.tfar);
  float t;
  Point2f uv;
  if (!shape->intersect(ray, t, uv) || !(t > ray.tmin && t < ray.tmax)) return;
  rh->ray.tfar = t;
  rh->hit.u = uv.x;
  rh->hit.v = uv.y;
  rh->hit.Ng_x = rh->hit.Ng_y = rh->hit.Ng_z = 0.0f;  // computeInteraction provides the normal
  rh->hit.primID = args->primID;
  rh->hit.geomID = args->geomID;
  rh->hit.instID[0] = args->context->instID[0];
}

void userOccluded(const RTCOccludedFunctionNArguments* args) {
  if (args->N != 1 || !args->valid[0]) return;
  auto* r = reinterpret_cast<RTCRay*>(args->ray);
  const auto* shape = static_cast<const Shape*>(args->geometryUserPtr);
  Ray ray(Point3f(r->org_x, r->org_y, r->org_z), Vec3f(r->dir_x, r->dir_y, r->dir_z), r->tnear, r->tfar);
  float t;
  Point2f uv;
  if (shape->intersect(ray, t, uv) && t > ray.tmin && t < ray.tmax) r->tfar = -Infinity;  // Embree's "occluded"
}

RTCRay toEmbree(const Ray& ray) {
  RTCRay r{};
  r.org_x = ray.o.x, r.org_y = ray.o.y, r.org_z = ray.o.z;
  r.dir_x = ray.d.x, r.dir_y = ray.d.y, r.dir_z = ray.d.z;
  r.tnear = ray.tmin;
  r.tfar = ray.tmax;
  r.mask = 0xFFFFFFFFu;
  r.flags = 0;
  r.time = 0.0f;
  return r;
}

}  // namespace

struct EmbreeAccel::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<const Shape*> byGeomId;
};

EmbreeAccel::EmbreeAccel(const std::vector<std::shared_ptr<Shape>>& shapes) : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) throw Error(str("cannot create the Embree device (error ", int(rtcGetDeviceError(nullptr)), ")"));
  rtcSetDeviceErrorFunction(impl_->device, deviceError, nullptr);
  impl_->scene = rtcNewScene(impl_->device);
  // Robust mode: exact edge tests, so rays through shared mesh edges never slip through.
  rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST);

  for (const auto& shape : shapes) {
    RTCGeometry geom;
    if (const TriangleMesh* mesh = shape->asMesh()) {
      geom = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
      // Embree-owned buffers: Embree pads them for its SIMD loads, which the
      // mesh's own vectors are not.
      auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                            3 * sizeof(float), mesh->vertexCount()));
      for (const Point3f& p : mesh->positions()) *v++ = p.x, *v++ = p.y, *v++ = p.z;
      auto* idx = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(uint32_t), mesh->triangleCount()));
      std::copy(mesh->indices().begin(), mesh->indices().end(), idx);
    } else {
      geom = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_USER);
      rtcSetGeometryUserPrimitiveCount(geom, 1);
      rtcSetGeometryUserData(geom, const_cast<Shape*>(shape.get()));
      rtcSetGeometryBoundsFunction(geom, userBounds, nullptr);
      rtcSetGeometryIntersectFunction(geom, userIntersect);
      rtcSetGeometryOccludedFunction(geom, userOccluded);
    }
    rtcCommitGeometry(geom);
    unsigned id = rtcAttachGeometry(impl_->scene, geom);
    rtcReleaseGeometry(geom);
    if (impl_->byGeomId.size() <= id) impl_->byGeomId.resize(id + 1, nullptr);
    impl_->byGeomId[id] = shape.get();
  }
  rtcCommitScene(impl_->scene);
}

EmbreeAccel::~EmbreeAccel() {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

bool EmbreeAccel::intersect(const Ray& ray, SurfaceInteraction& si) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  rh.ray = toEmbree(ray);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;

  const Shape* shape = impl_->byGeomId[rh.hit.geomID];
  shape->computeInteraction(ray, rh.ray.tfar, rh.hit.primID, Point2f(rh.hit.u, rh.hit.v), si);
  si.t = rh.ray.tfar;
  si.shape = shape;
  si.primIndex = rh.hit.primID;
  si.wi = si.toLocal(normalize(-ray.d));
  return true;
}

bool EmbreeAccel::occluded(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r = toEmbree(ray);
  rtcOccluded1(impl_->scene, &context, &r);
  return r.tfar < 0.0f;  // Embree sets tfar = -inf on a hit
}

}  // namespace femto::detail
