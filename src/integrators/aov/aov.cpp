// aov: arbitrary output variables (Mitsuba 3's `aov`). Writes a multi-channel
// OpenEXR image with geometric information about what each camera ray hits,
// optionally preceded by the R, G, B channels of a nested integrator.
//
// `aovs` lists "name:type" pairs separated by commas, in Mitsuba 3 syntax,
// e.g. "dd.y:depth,nn:sh_normal". Each type gives channels named
// "<name>.<suffix>":
//
// | type        | channels  | value (world space; 0 where the ray escapes)              |
// |-------------|-----------|-----------------------------------------------------------|
// | depth       | .T        | distance from the sensor to the hit point                 |
// | position    | .X .Y .Z  | hit point                                                 |
// | geo_normal  | .X .Y .Z  | geometric normal                                          |
// | sh_normal   | .X .Y .Z  | shading normal                                            |
// | uv          | .U .V     | surface parameterisation                                  |
// | albedo      | .R .G .B  | directional reflectance of the BSDF toward the camera, estimated by one BSDF sample per camera sample (exact for diffuse) |
// | shape_index | .T        | index of the hit shape in the scene's shape list (-1 where the ray escapes) |
//
// Pixels are filtered averages of their samples like any image: use a box
// <rfilter> (and few samples) where values must not blend across edges.
// The film only provides size, crop window and filter: this integrator
// develops and writes its own image (EXR only, no PNG preview).
//
// | name         | type       | default | meaning                               |
// |--------------|------------|---------|---------------------------------------|
// | aovs         | string     | —       | "name:type" list, as above            |
// | (integrator) | integrator | none    | optional: its radiance becomes R,G,B  |
#include <sstream>
#include <unordered_map>

#include <femto/core/plugin.h>
#include <femto/render/bsdf.h>
#include <femto/film/channel_output.h>
#include <femto/render/integrator.h>
#include <femto/loop/render_loop.h>
#include <femto/render/scene.h>

namespace femto {

class AOVIntegrator final : public Integrator {
 public:
  enum class Type { Depth, Position, GeoNormal, ShNormal, UV, Albedo, ShapeIndex };

  explicit AOVIntegrator(const Properties& props) {
    if (ObjectRef inner = props.objectOfKind(ObjectKind::Integrator)) {
      inner_ = std::dynamic_pointer_cast<SamplingIntegrator>(inner);
      if (!inner_) throw Error(props.location(), "the nested <integrator> of \"aov\" must estimate radiance per camera ray");
      channelNames_ = {"R", "G", "B"};
    }
    std::string list = props.getString("aovs");
    std::stringstream entries(list);
    std::string entry;
    while (std::getline(entries, entry, ',')) {
      size_t colon = entry.find(':');
      if (colon == std::string::npos || colon == 0 || colon + 1 == entry.size())
        props.raise("aovs", str("expected \"name:type\" entries separated by commas, got \"", entry, "\""));
      std::string name = entry.substr(0, colon), type = entry.substr(colon + 1);
      Type t = parseType(props, type);
      aovs_.push_back(t);
      for (const char* suffix : suffixes(t)) channelNames_.push_back(name + "." + suffix);
    }
    if (aovs_.empty()) props.raise("aovs", "lists no output variables");
  }

  RenderStats render(const Scene& scene, const RenderOptions& options) const override {
    const Sensor& sensor = scene.sensor();
    const Film& film = sensor.film();
    const int channels = int(channelNames_.size());
    std::unordered_map<const Shape*, int> shapeIndex;
    for (size_t i = 0; i < scene.shapes().size(); ++i) shapeIndex[scene.shapes()[i].get()] = int(i);

    auto sampleFn = [&](const Point2f& filmPos, Sampler& sampler, float* out) {
      Ray ray;
      Color3f weight = sensor.sampleRay(filmPos, sampler.next2D(), ray);
      if (inner_) {
        Color3f L = weight.isBlack() ? Color3f(0.0f) : weight * inner_->Li(ray, scene, sampler);
        *out++ = L.r, *out++ = L.g, *out++ = L.b;
      }
      SurfaceInteraction si;
      bool hit = !weight.isBlack() && scene.rayIntersect(ray, si);
      for (Type t : aovs_) out = writeAOV(t, hit, si, shapeIndex, sampler, out);
    };
    ImageBlock result(film.cropOffset(), film.cropSize(), film.filter(), channels);
    RenderStats stats = renderChannelTiles(scene, options, sampleFn, result);
    if (!options.output.empty()) developChannels(result, film, channelNames_, options.output);
    return stats;
  }

  const std::vector<std::string>& channelNames() const { return channelNames_; }

  std::string toString() const override {
    std::string names;
    for (const auto& n : channelNames_) names += (names.empty() ? "" : ", ") + n;
    return str("AOVIntegrator[channels=", names, "]");
  }

 private:
  static Type parseType(const Properties& props, const std::string& type) {
    static const std::pair<const char*, Type> table[] = {
        {"depth", Type::Depth},       {"position", Type::Position}, {"geo_normal", Type::GeoNormal},
        {"sh_normal", Type::ShNormal}, {"uv", Type::UV},            {"albedo", Type::Albedo},
        {"shape_index", Type::ShapeIndex}};
    for (const auto& [name, t] : table)
      if (type == name) return t;
    props.raise("aovs", str("unknown AOV type \"", type,
                            "\" (expected depth, position, geo_normal, sh_normal, uv, albedo or shape_index)"));
  }

  static std::vector<const char*> suffixes(Type t) {
    switch (t) {
      case Type::Depth:
      case Type::ShapeIndex: return {"T"};
      case Type::UV: return {"U", "V"};
      case Type::Albedo: return {"R", "G", "B"};
      default: return {"X", "Y", "Z"};
    }
  }

  static float* writeVector(const Vec3f& v, float* out) {
    *out++ = v.x, *out++ = v.y, *out++ = v.z;
    return out;
  }

  static float* writeAOV(Type t, bool hit, const SurfaceInteraction& si,
                         const std::unordered_map<const Shape*, int>& shapeIndex, Sampler& sampler, float* out) {
    switch (t) {
      case Type::Depth: *out++ = hit ? si.t : 0.0f; return out;
      case Type::Position: return writeVector(hit ? Vec3f(si.p) : Vec3f(0.0f), out);
      case Type::GeoNormal: return writeVector(hit ? Vec3f(si.n) : Vec3f(0.0f), out);
      case Type::ShNormal: return writeVector(hit ? si.sh.n : Vec3f(0.0f), out);
      case Type::UV:
        *out++ = hit ? si.uv.x : 0.0f;
        *out++ = hit ? si.uv.y : 0.0f;
        return out;
      case Type::Albedo: {
        // One BSDF sample's weight f |cos| / pdf is an unbiased estimate of the
        // directional reflectance at wi (exact for a Lambertian BSDF).
        Color3f albedo(0.0f);
        const BSDF* bsdf = hit ? si.bsdf() : nullptr;
        float u1 = sampler.next1D();
        Point2f u2 = sampler.next2D();
        if (bsdf) {
          BSDFSample bs;
          albedo = bsdf->sample(si, u1, u2, bs);
          if (!(bs.pdf > 0.0f)) albedo = Color3f(0.0f);
        }
        *out++ = albedo.r, *out++ = albedo.g, *out++ = albedo.b;
        return out;
      }
      case Type::ShapeIndex: {
        auto it = hit ? shapeIndex.find(si.shape) : shapeIndex.end();
        *out++ = it == shapeIndex.end() ? -1.0f : float(it->second);
        return out;
      }
    }
    return out;
  }

  std::shared_ptr<SamplingIntegrator> inner_;
  std::vector<Type> aovs_;
  std::vector<std::string> channelNames_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::AOVIntegrator, Integrator, "aov", "arbitrary output variables (depth, normals, ...) as EXR channels")
