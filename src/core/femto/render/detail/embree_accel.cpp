// Embree 3 scene: the only file of femto that includes Embree.
#include <femto/render/detail/embree_accel.h>

#include <map>
#include <type_traits>

#include <embree3/rtcore.h>

#include <femto/base/thread_edges.h>
#include <femto/core/log.h>
#include <femto/render/mesh.h>
#include <femto/render/shape.h>
#include <femto/render/shape_group.h>

namespace femto::detail {
namespace {

void deviceError(void*, RTCError code, const char* message) {
  logError("Embree error ", int(code), ": ", message ? message : "(no message)");
}

// --- user geometry callbacks for analytic shapes (one primitive per shape) ---

// Embree calls userBounds on its own (TBB) threads while it builds a scene,
// inside libembree where ThreadSanitizer sees no synchronisation: each shape
// is handed over when it is attached, and what the callbacks did is handed
// back to the thread whose rtcCommitScene returns (commit(); base/thread_edges.h).
char builtScenes = 0;

void commit(RTCScene scene) {
  rtcCommitScene(scene);
  acquireFrom(&builtScenes);
}

void userBounds(const RTCBoundsFunctionArguments* args) {
  acquireFrom(args->geometryUserPtr);
  const auto* shape = static_cast<const Shape*>(args->geometryUserPtr);
  BoundingBox3f b = shape->bbox();
  *args->bounds_o = RTCBounds{b.min.x, b.min.y, b.min.z, 0.0f, b.max.x, b.max.y, b.max.z, 0.0f};
  releaseTo(&builtScenes);
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

/// A geometry id of the top-level Embree scene: a shape, or an instance whose
/// hits carry the geometry id of a shape of its group.
struct TopLevelEntry {
  const Shape* shape = nullptr;
  const ShapeInstance* instance = nullptr;
  const std::vector<const Shape*>* groupShapes = nullptr;  // the instanced group's shapes by geometry id
};

/// A shapegroup's own Embree scene, shared by all its instances.
struct GroupScene {
  RTCScene scene = nullptr;
  std::vector<const Shape*> byGeomId;
};

RTCGeometry newShapeGeometry(RTCDevice device, const Shape& shape) {
  RTCGeometry geom;
  if (const TriangleMesh* mesh = shape.asMesh()) {
    geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree-owned buffers: Embree pads them for its SIMD loads, which the
    // mesh's own vectors are not.
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), mesh->vertexCount()));
    for (const Point3f& p : mesh->positions()) *v++ = p.x, *v++ = p.y, *v++ = p.z;
    auto* idx = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(uint32_t), mesh->triangleCount()));
    std::copy(mesh->indices().begin(), mesh->indices().end(), idx);
  } else {
    geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geom, 1);
    rtcSetGeometryUserData(geom, const_cast<Shape*>(&shape));
    releaseTo(&shape);  // to userBounds on Embree's build threads
    rtcSetGeometryBoundsFunction(geom, userBounds, nullptr);
    rtcSetGeometryIntersectFunction(geom, userIntersect);
    rtcSetGeometryOccludedFunction(geom, userOccluded);
  }
  return geom;
}

/// Commit `geom`, attach it to `scene` and return its id (the scene keeps the geometry alive).
unsigned attach(RTCScene scene, RTCGeometry geom) {
  rtcCommitGeometry(geom);
  unsigned id = rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  return id;
}

RTCScene newScene(RTCDevice device) {
  RTCScene scene = rtcNewScene(device);
  // Robust mode: exact edge tests, so rays through shared mesh edges never slip through.
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  return scene;
}

template <typename T>
void store(std::vector<T>& table, unsigned id, std::type_identity_t<T> value) {
  if (table.size() <= id) table.resize(id + 1);
  table[id] = value;
}

}  // namespace

struct EmbreeAccel::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<TopLevelEntry> byGeomId;
  std::map<const ShapeGroup*, GroupScene> groups;

  /// The group's Embree scene, built on first use.
  const GroupScene& groupScene(const ShapeGroup& group) {
    auto [it, inserted] = groups.try_emplace(&group);
    GroupScene& gs = it->second;
    if (inserted) {
      gs.scene = newScene(device);
      for (const auto& shape : group.shapes())
        store(gs.byGeomId, attach(gs.scene, newShapeGeometry(device, *shape)), shape.get());
      commit(gs.scene);
    }
    return gs;
  }
};

EmbreeAccel::EmbreeAccel(const std::vector<std::shared_ptr<Shape>>& shapes) : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) throw Error(str("cannot create the Embree device (error ", int(rtcGetDeviceError(nullptr)), ")"));
  rtcSetDeviceErrorFunction(impl_->device, deviceError, nullptr);
  impl_->scene = newScene(impl_->device);

  for (const auto& shape : shapes) {
    if (dynamic_cast<const ShapeGroup*>(shape.get())) continue;  // seen only through its instances
    TopLevelEntry entry{shape.get()};
    RTCGeometry geom;
    if (const auto* instance = dynamic_cast<const ShapeInstance*>(shape.get())) {
      const GroupScene& group = impl_->groupScene(instance->group());
      geom = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_INSTANCE);
      rtcSetGeometryInstancedScene(geom, group.scene);
      const Matrix4f& m = instance->toWorld().matrix();
      float rows[12];  // the affine 3x4 part, row-major
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) rows[4 * r + c] = m.m[r][c];
      rtcSetGeometryTransform(geom, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, rows);
      entry.instance = instance;
      entry.groupShapes = &group.byGeomId;
    } else {
      geom = newShapeGeometry(impl_->device, *shape);
    }
    store(impl_->byGeomId, attach(impl_->scene, geom), entry);
  }
  commit(impl_->scene);
}

EmbreeAccel::~EmbreeAccel() {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  for (auto& [group, gs] : impl_->groups) rtcReleaseScene(gs.scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

namespace {

/// rtcIntersect1 on `ray`; geomID is RTC_INVALID_GEOMETRY_ID on a miss.
RTCRayHit traceNearest(RTCScene scene, const Ray& ray) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  rh.ray = toEmbree(ray);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &context, &rh);
  return rh;
}

}  // namespace

bool EmbreeAccel::intersect(const Ray& ray, SurfaceInteraction& si) const {
  PreliminaryHit hit;
  if (!intersectPreliminary(ray, hit)) return false;
  computeInteraction(ray, hit, si);
  return true;
}

bool EmbreeAccel::intersectPreliminary(const Ray& ray, PreliminaryHit& hit) const {
  RTCRayHit rh = traceNearest(impl_->scene, ray);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  hit.t = rh.ray.tfar;
  hit.instanceId = rh.hit.instID[0];
  hit.primIndex = rh.hit.primID;
  hit.uv = Point2f(rh.hit.u, rh.hit.v);
  // Embree reports an instance as instID and the group's own geometry as geomID.
  hit.shape = hit.instanceId == RTC_INVALID_GEOMETRY_ID ? impl_->byGeomId[rh.hit.geomID].shape
                                                        : (*impl_->byGeomId[hit.instanceId].groupShapes)[rh.hit.geomID];
  return true;
}

void EmbreeAccel::computeInteraction(const Ray& ray, const PreliminaryHit& hit, SurfaceInteraction& si) const {
  if (hit.instanceId == RTC_INVALID_GEOMETRY_ID) {
    hit.shape->computeInteraction(ray, hit.t, hit.primIndex, hit.uv, si);
  } else {
    // t is shared with the instance's local ray: its direction is not renormalised.
    const TopLevelEntry& entry = impl_->byGeomId[hit.instanceId];
    hit.shape->computeInteraction(entry.instance->toLocal().ray(ray), hit.t, hit.primIndex, hit.uv, si);
    entry.instance->interactionToWorld(si);
  }
  si.t = hit.t;
  si.shape = hit.shape;
  si.primIndex = hit.primIndex;
  si.wi = si.toLocal(normalize(-ray.d));
}

float EmbreeAccel::hitDistance(const Ray& ray) const {
  RTCRayHit rh = traceNearest(impl_->scene, ray);
  return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? Infinity : rh.ray.tfar;
}

bool EmbreeAccel::occluded(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r = toEmbree(ray);
  rtcOccluded1(impl_->scene, &context, &r);
  return r.tfar < 0.0f;  // Embree sets tfar = -inf on a hit
}

}  // namespace femto::detail
