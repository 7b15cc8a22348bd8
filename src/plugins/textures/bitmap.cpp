// bitmap: an image file as a texture, read through the core's readImage
// (OpenImageIO: PNG, JPEG, EXR, HDR, ...). Lookups follow Mitsuba: uv (0, 0)
// is the top-left corner of the image, texel centres sit at
// ((x + 0.5) / width, (y + 0.5) / height), and bilinear filtering blends the
// four centres around a point. Greyscale images give grey colours; alpha is
// ignored.
//
// Unless `raw` is set, integer images (8/16-bit PNG, JPEG, ...) are taken to
// store sRGB-encoded values and are converted to linear once at load time, as
// Mitsuba does; float images (EXR, HDR) are linear already.
//
// | name             | type      | default  | meaning                                                 | unit |
// |------------------|-----------|----------|---------------------------------------------------------|------|
// | filename         | string    | required | image file (the loader resolves relative names)        | -    |
// | raw              | boolean   | false    | use stored values as they are (no sRGB decoding)        | -    |
// | filter_type      | string    | bilinear | "bilinear" or "nearest" (Mitsuba 0.6's "ewa" and "trilinear" read as bilinear: no mip-maps) | - |
// | wrap_mode        | string    | repeat   | outside [0, 1): "repeat", "mirror" or "clamp"           | -    |
// | wrap_mode_u, _v  | string    | wrap_mode| per axis (Mitsuba 0.6's wrapModeU / wrapModeV)          | -    |
// | gamma            | float     | from file| Mitsuba 0.6: -1 decodes sRGB, 1 is linear, else v^gamma | -    |
// | max_anisotropy   | float     | 20       | Mitsuba 0.6 EWA setting, accepted with filter_type ewa and ignored | - |
// | to_uv            | transform | identity | maps surface uv to image uv                             | -    |
// | uscale, vscale   | float     | 1        | Mitsuba 0.6 alternative to to_uv: uv * scale + offset   | -    |
// | uoffset, voffset | float     | 0        | (see uscale)                                            | -    |
#include <algorithm>
#include <cmath>

#include <femto/core/log.h>
#include <femto/core/plugin.h>
#include <femto/image/image_io.h>
#include <femto/image/texel_lookup.h>
#include <femto/render/texture.h>

namespace femto {

class BitmapTexture final : public Texture {
 public:
  explicit BitmapTexture(const Properties& props)
      : filename_(props.getString("filename")), raw_(props.getBool("raw", false)), toUv_(props) {
    readFilterType(props);
    WrapMode both = readWrapMode(props, "wrap_mode", WrapMode::Repeat);
    wrapU_ = readWrapMode(props, "wrap_mode_u", both);
    wrapV_ = readWrapMode(props, "wrap_mode_v", both);

    ImageFileInfo info;
    try {
      image_ = toRGB(readImage(filename_, info));
    } catch (const Error& e) {
      props.raise("filename", e.what());
    }
    if (image_.width <= 0 || image_.height <= 0) props.raise("filename", str("image \"", filename_, "\" is empty"));
    // Mitsuba 0.6's `gamma` overrides what the file says: -1 is sRGB, 1 linear.
    float gamma = props.getFloat("gamma", raw_ || !info.srgbEncoded ? 1.0f : -1.0f);
    if (!(gamma == -1.0f || gamma > 0.0f))
      props.raise("gamma", str("must be -1 (sRGB) or a positive exponent, got ", gamma));
    decodedSRGB_ = gamma == -1.0f;
    double sum[3] = {0, 0, 0};
    for (float& v : image_.data) {
      if (decodedSRGB_) v = srgbToLinear(v);
      else if (gamma != 1.0f) v = std::pow(std::max(v, 0.0f), gamma);
      if (!std::isfinite(v)) props.raise("filename", str("image \"", filename_, "\" contains non-finite values"));
    }
    for (size_t i = 0; i < image_.data.size(); ++i) sum[i % 3] += image_.data[i];
    double texels = double(image_.width) * image_.height;
    mean_ = Color3f(float(sum[0] / texels), float(sum[1] / texels), float(sum[2] / texels));
  }

  Color3f eval(const SurfaceInteraction& si) const override {
    Point2f uv = toUv_(si.uv);
    return bilinear_ ? lookupBilinear(image_, uv, wrapU_, wrapV_) : lookupNearest(image_, uv, wrapU_, wrapV_);
  }

  /// Mean over texels: exact for nearest lookups and, up to the border
  /// treatment, for bilinear ones.
  Color3f mean() const override { return mean_; }
  Point2i resolution() const override { return Point2i(image_.width, image_.height); }

  std::string toString() const override {
    return str("BitmapTexture[filename=\"", filename_, "\", ", image_.width, "x", image_.height,
               ", filter_type=", bilinear_ ? "bilinear" : "nearest", ", wrap_mode=", wrapModeName(wrapU_), "/", wrapModeName(wrapV_),
               ", srgb_decoded=", decodedSRGB_ ? "true" : "false", "]");
  }

 private:
  static WrapMode readWrapMode(const Properties& props, const std::string& name, WrapMode def) {
    if (!props.has(name)) return def;
    std::string text = props.getString(name);
    WrapMode mode;
    if (!parseWrapMode(text, mode))
      props.raise(name, str("unknown wrap mode \"", text, "\" (expected \"repeat\", \"mirror\" or \"clamp\")"));
    return mode;
  }

  void readFilterType(const Properties& props) {
    std::string filter = props.getString("filter_type", "bilinear");
    if (filter == "nearest") {
      bilinear_ = false;
    } else if (filter == "ewa" || filter == "trilinear") {
      props.getFloat("max_anisotropy", 20.0f);  // Mitsuba 0.6's EWA setting: read, meaningless without EWA
      SourceLocation where = props.location("filter_type");
      logWarn(where.known() ? where.toString() + ": " : "", "bitmap filter_type \"", filter,
              "\" is rendered as \"bilinear\" (femto has no mip-mapped filtering)");
    } else if (filter != "bilinear") {
      props.raise("filter_type", str("unknown filter type \"", filter, "\" (expected \"bilinear\" or \"nearest\")"));
    }
  }

  std::string filename_;
  bool raw_;
  UvMapping toUv_;
  bool bilinear_ = true;
  WrapMode wrapU_ = WrapMode::Repeat, wrapV_ = WrapMode::Repeat;
  bool decodedSRGB_ = false;
  Bitmap image_;
  Color3f mean_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::BitmapTexture, Texture, "bitmap", "Image file texture (bilinear or nearest lookups)")
