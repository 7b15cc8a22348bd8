// envmap: an environment lit by a latitude-longitude image (EXR, HDR, ...),
// with Mitsuba's mapping: +y is up; in the emitter's frame direction
//   d = (sin(theta) sin(phi), cos(theta), -sin(theta) cos(phi))
// reads image uv = (phi / 2 pi, theta / pi): the top row is the zenith (+y),
// the image's left edge looks along -z and its centre along +z.
// Lookups are bilinear between texel centres, repeating in u and clamped in v.
//
// Importance sampling: a piecewise-constant 2D distribution over texels
// (math/distribution.h) with weights luminance * (solid angle of the texel's
// row), i.e. luminance * sin(theta) integrated over the row exactly, and
// within a texel cos(theta) uniform rather than theta. The density is then
// constant in solid angle over each texel, and a constant image gives exactly
// 1 / (4 pi), the density of the `constant` emitter. The luminance is that
// of the bilinear lookups averaged over the texel (see buildDistribution), so
// every direction that can return light can be sampled.
//
// | name            | type      | default  | meaning                                           | unit                     |
// |-----------------|-----------|----------|---------------------------------------------------|--------------------------|
// | filename        | string    | required | latitude-longitude image, linear (EXR, HDR, PFM)  | -                        |
// | scale           | float     | 1        | multiplies the image                              | -                        |
// | to_world        | transform | identity | orientation of the map (a rotation)               | -                        |
// | sampling_weight | float     | 1        | relative probability of being picked for NEE      | -                        |
#include <femto/core/plugin.h>
#include <femto/image/image_io.h>
#include <femto/image/texel_lookup.h>
#include <femto/math/distribution.h>
#include <femto/math/transform.h>
#include <femto/transport/distant_emission.h>
#include <femto/render/emitter.h>

namespace femto {

class EnvironmentMap final : public Emitter {
 public:
  explicit EnvironmentMap(const Properties& props)
      : Emitter(props),
        filename_(props.getString("filename")),
        scale_(props.getFloat("scale", 1.0f, Range::nonNegative())),
        toWorld_(props.getTransform("to_world", Transform())) {
    try {
      image_ = toRGB(readImage(filename_));
    } catch (const Error& e) {
      props.raise("filename", e.what());
    }
    if (image_.width <= 0 || image_.height <= 0) props.raise("filename", str("image \"", filename_, "\" is empty"));
    for (float& v : image_.data) {
      if (!std::isfinite(v) || v < 0.0f)
        props.raise("filename", str("environment map \"", filename_, "\" contains negative or non-finite values"));
      v *= scale_;
    }
    buildDistribution();
  }

  bool isDelta() const override { return false; }
  bool isEnvironment() const override { return true; }
  void setScene(const Scene& scene) override { sphere_ = SceneSphere::of(scene); }

  Color3f sampleDirection(const Point3f& ref, const Point2f& u, DirectionSample& ds) const override {
    float pdf = 0.0f;
    Vec3f d = sampleWorldDirection(u, pdf);
    ds = sphere_.directionSample(ref, d);
    if (!(pdf > 0.0f)) return Color3f(0.0f);
    ds.pdf = pdf;
    return radiance(d) / pdf;
  }

  float pdfDirection(const Point3f&, const DirectionSample& ds) const override {
    Vec3f local = normalize(toWorld_.inverse().vector(ds.d));
    Point2f uv = uvOf(local);
    int row = std::min(int(uv.y * float(image_.height)), image_.height - 1);
    return distribution_.pdf(Point2f(uv.x, (float(row) + 0.5f) / float(image_.height))) / texelSolidAngleScale(row);
  }

  Color3f evalEnvironment(const Ray& ray) const override { return radiance(normalize(ray.d)); }

  /// Direction by the map's distribution, origin uniform on the scene's disk
  /// facing it: weight L(d) pi R^2 / pdf(d).
  Color3f sampleRay(const Point2f& uPosition, const Point2f& uDirection, Ray& ray) const override {
    float pdf = 0.0f;
    Vec3f towardEmitter = sampleWorldDirection(uDirection, pdf);
    ray = sphere_.rayAlong(-towardEmitter, uPosition);
    return pdf > 0.0f ? radiance(towardEmitter) * (sphere_.diskArea() / pdf) : Color3f(0.0f);
  }

  /// Flux into the scene's bounding sphere: pi R^2 times the radiance
  /// integrated over all directions (integrateRadiance).
  Color3f power() const override { return radianceIntegral_ * sphere_.diskArea(); }

  std::string toString() const override {
    return str("EnvironmentMap[filename=\"", filename_, "\", ", image_.width, "x", image_.height, ", scale=", scale_, "]");
  }

 private:
  float thetaOfRow(int row) const { return Pi * float(row) / float(image_.height); }
  /// 2 pi H (cos theta_row - cos theta_row+1): density on the unit square of
  /// the distribution divided by this is density per solid angle.
  float texelSolidAngleScale(int row) const {
    return 2.0f * Pi * float(image_.height) * (std::cos(thetaOfRow(row)) - std::cos(thetaOfRow(row + 1)));
  }

  /// Sampling weights: the luminance each texel's footprint receives from
  /// bilinear lookups, i.e. the image filtered by (1/8, 3/4, 1/8) along each
  /// axis (the integral of the linear interpolant over one texel), times the
  /// solid angle of the texel's row. Filtering keeps the density positive
  /// wherever a lookup can return light (next to a bright texel), which
  /// photon emission needs: it has no second strategy to find that light.
  void buildDistribution() {
    const int w = image_.width, h = image_.height;
    std::vector<float> lum(size_t(w) * h), alongU(size_t(w) * h), weights(size_t(w) * h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) lum[size_t(y) * w + x] = texel(image_, x, y, WrapMode::Clamp, WrapMode::Clamp).luminance();
    auto at = [&](const std::vector<float>& img, int x, int y) {
      return img[size_t(wrapTexelIndex(y, h, WrapMode::Clamp)) * w + size_t(wrapTexelIndex(x, w, WrapMode::Repeat))];
    };
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        alongU[size_t(y) * w + x] = 0.125f * at(lum, x - 1, y) + 0.75f * at(lum, x, y) + 0.125f * at(lum, x + 1, y);
    for (int y = 0; y < h; ++y) {
      float rowSolidAngle = std::cos(thetaOfRow(y)) - std::cos(thetaOfRow(y + 1));  // times 2 pi / w per texel
      for (int x = 0; x < w; ++x) {
        float filtered = 0.125f * at(alongU, x, y - 1) + 0.75f * at(alongU, x, y) + 0.125f * at(alongU, x, y + 1);
        weights[size_t(y) * w + x] = filtered * rowSolidAngle;
      }
    }
    distribution_ = Distribution2D(weights, w, h);
    radianceIntegral_ = integrateRadiance();
  }

  /// Integral of the bilinearly interpolated radiance over all directions,
  /// exactly. Over a full turn of u the interpolant integrates to the mean of
  /// its row, so with M(v) the row means interpolated linearly between row
  /// centres (constant beyond the first and last), and d omega =
  /// 2 pi du * pi sin(pi v) dv, the integral is 2 pi^2 int_0^1 M(v) sin(pi v) dv,
  /// summed over the pieces where M is linear.
  Color3f integrateRadiance() const {
    const int w = image_.width, h = image_.height;
    std::vector<Color3f> rowMean(static_cast<size_t>(h));
    for (int y = 0; y < h; ++y) {
      double sum[3] = {0, 0, 0};
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 3; ++c) sum[c] += image_.pixel(x, y)[c];
      rowMean[size_t(y)] = Color3f(float(sum[0] / w), float(sum[1] / w), float(sum[2] / w));
    }
    // int_a^b (p + q v) sin(pi v) dv from the antiderivatives of sin(pi v) and v sin(pi v).
    auto F0 = [](double v) { return -std::cos(Pi * v) / Pi; };
    auto F1 = [](double v) { return -v * std::cos(Pi * v) / Pi + std::sin(Pi * v) / (double(Pi) * Pi); };
    auto linearPiece = [&](double a, double A, double b, double B) {
      double q = (B - A) / (b - a), p = A - q * a;
      return p * (F0(b) - F0(a)) + q * (F1(b) - F1(a));
    };
    auto centre = [&](int y) { return (y + 0.5) / h; };
    Color3f result;
    for (int c = 0; c < 3; ++c) {
      double integral = linearPiece(0.0, rowMean[0][c], centre(0), rowMean[0][c]) +
                        linearPiece(centre(h - 1), rowMean[size_t(h - 1)][c], 1.0, rowMean[size_t(h - 1)][c]);
      for (int y = 0; y + 1 < h; ++y)
        integral += linearPiece(centre(y), rowMean[size_t(y)][c], centre(y + 1), rowMean[size_t(y + 1)][c]);
      result[c] = float(2.0 * Pi * Pi * integral);
    }
    return result;
  }

  /// Image uv of a unit direction in the map's frame.
  static Point2f uvOf(const Vec3f& d) {
    float phi = std::atan2(d.x, -d.z);
    if (phi < 0.0f) phi += 2.0f * Pi;
    float u = std::min(phi * Inv2Pi, 0.99999994f);
    float v = std::min(std::acos(std::clamp(d.y, -1.0f, 1.0f)) * InvPi, 0.99999994f);
    return {u, v};
  }

  Color3f radiance(const Vec3f& worldDirection) const {
    Point2f uv = uvOf(normalize(toWorld_.inverse().vector(worldDirection)));
    return lookupBilinear(image_, uv, WrapMode::Repeat, WrapMode::Clamp);
  }

  Vec3f sampleWorldDirection(const Point2f& u, float& pdf) const {
    float pdfSquare = 0.0f;
    Point2f uv = distribution_.sample(u, &pdfSquare);
    // Within the row, cos(theta) is uniform (see the header comment).
    float rowPosition = uv.y * float(image_.height);
    int row = std::min(int(rowPosition), image_.height - 1);
    float within = rowPosition - float(row);
    float cosTheta = std::cos(thetaOfRow(row)) * (1.0f - within) + std::cos(thetaOfRow(row + 1)) * within;
    float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    float phi = 2.0f * Pi * uv.x;
    Vec3f local(sinTheta * std::sin(phi), cosTheta, -sinTheta * std::cos(phi));
    pdf = pdfSquare / texelSolidAngleScale(row);
    return normalize(toWorld_.vector(local));
  }

  std::string filename_;
  float scale_;
  Transform toWorld_;
  Bitmap image_;
  Distribution2D distribution_;
  Color3f radianceIntegral_;
  SceneSphere sphere_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::EnvironmentMap, Emitter, "envmap", "Environment lit by a latitude-longitude image")
