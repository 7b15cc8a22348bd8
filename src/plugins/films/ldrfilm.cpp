// Mitsuba 0.6's low dynamic range film: develops the crop window, tone maps
// it and writes an 8-bit PNG or JPEG, as the scene asks; the linear float32
// OpenEXR is written beside it (same stem) for femto's analysis tools.
//
// Tone mapping (applied to the linear RGB values v, exposure e):
// - "gamma": v 2^e, clamped to [0, 1], then the sRGB curve (gamma = -1) or
//   v^(1/gamma).
// - "reinhard": the global operator of Reinhard et al., "Photographic Tone
//   Reproduction for Digital Images", SIGGRAPH 2002, eq. 2-4, on luminance
//   Y (Rec. 709 weights) of v 2^e: L = key Y / Y_avg (Y_avg the log-average,
//   eq. 1), L_d = L (1 + L / L_white^2) / (1 + L) with L_white = (1 - burn)
//   times the largest L (burn = 0: the brightest pixel maps to 1; burn -> 1:
//   more burns out); colours keep their ratios (v L_d / Y); then the display curve.
//
// | name               | type    | default   | meaning                                            |
// |--------------------|---------|-----------|----------------------------------------------------|
// | width, height, crop_* | integer | 768x576 | as hdrfilm                                         |
// | file_format        | string  | "png"     | png or jpeg                                        |
// | pixel_format       | string  | "rgb"     | rgb (rgba, luminance, ...: warning, RGB is written)|
// | tonemap_method     | string  | "gamma"   | gamma or reinhard                                  |
// | gamma              | float   | -1        | display gamma; -1 = the sRGB curve                 |
// | exposure           | float   | 0         | exposure in stops (scale 2^exposure)               |
// | key                | float   | 0.18      | reinhard: the key value                            |
// | burn               | float   | 0         | reinhard: how much highlights may burn out, [0, 1] |
// | banner             | boolean | false     | Mitsuba 0.x banner overlay: ignored                |
// | high_quality_edges | boolean | false     | as hdrfilm                                         |
// | (nested rfilter)   | rfilter | gaussian  | pixel reconstruction filter                        |
#include <algorithm>
#include <cmath>

#include <femto/core/log.h>
#include <femto/core/plugin.h>
#include <femto/image/image_io.h>
#include <femto/render/film.h>

namespace femto {

class LDRFilm final : public Film {
 public:
  explicit LDRFilm(const Properties& props) : Film(props) {
    std::string format = props.getString("file_format", "png");
    if (format == "png") extension_ = ".png";
    else if (format == "jpeg" || format == "jpg") extension_ = ".jpg";
    else props.raise("file_format", str("expected \"png\" or \"jpeg\", got \"", format, "\""));
    std::string pixelFormat = props.getString("pixel_format", "rgb");
    if (pixelFormat != "rgb") {
      SourceLocation where = props.location("pixel_format");
      logWarn(where.known() ? where.toString() + ": " : std::string(), "ldrfilm pixel_format \"", pixelFormat,
              "\" is not supported; writing RGB");
    }
    std::string method = props.getString("tonemap_method", "gamma");
    if (method != "gamma" && method != "reinhard")
      props.raise("tonemap_method", str("expected \"gamma\" or \"reinhard\", got \"", method, "\""));
    reinhard_ = method == "reinhard";
    gamma_ = props.getFloat("gamma", -1.0f);
    if (!(gamma_ == -1.0f || gamma_ > 0.0f)) props.raise("gamma", str("must be -1 (sRGB) or positive, got ", gamma_));
    exposure_ = props.getFloat("exposure", 0.0f);
    if (!std::isfinite(exposure_)) props.raise("exposure", "must be finite");
    key_ = props.getFloat("key", 0.18f);
    if (!(key_ > 0.0f)) props.raise("key", str("must be positive, got ", key_));
    burn_ = props.getFloat("burn", 0.0f);
    if (!(burn_ >= 0.0f && burn_ <= 1.0f)) props.raise("burn", str("must be in [0, 1], got ", burn_));
    props.getBool("banner", false);
    props.getBool("high_quality_edges", false);
  }

  /// An output named .png or .jpg is written in that format (the scene's
  /// file_format otherwise), with the linear EXR beside it.
  void develop(const ImageBlock& image, const std::filesystem::path& path) const override {
    Bitmap linear = developCrop(image);
    std::filesystem::path exr = path, ldr = path;
    exr.replace_extension(".exr");
    if (!isDisplayExtension(path.extension().string())) ldr.replace_extension(extension_);
    writeEXR(exr, linear);
    writeDisplayImage(ldr, toneMapped(linear));
  }

  void checkOutputPath(const std::filesystem::path& path) const override {
    std::string ext = path.extension().string();
    if (!ext.empty() && ext != ".exr" && !isDisplayExtension(ext))
      throw Error(str("cannot write \"", path.string(), "\": ldrfilm writes .png or .jpg (and the linear .exr beside it), not \"",
                      ext, "\""));
  }

  std::string defaultExtension() const override { return extension_; }

  /// Display-encoded values in [0, 1] (see the header comment).
  Bitmap toneMapped(const Bitmap& linear) const {
    Bitmap out = linear;
    const float scale = std::exp2(exposure_);
    for (float& v : out.data) v *= scale;
    if (reinhard_) applyReinhard(out);
    for (float& v : out.data) v = encode(std::clamp(v, 0.0f, 1.0f));
    return out;
  }

  std::string toString() const override {
    return str("LDRFilm[size=", size().x, "x", size().y, ", tonemap=", reinhard_ ? "reinhard" : "gamma", ", gamma=", gamma_,
               ", exposure=", exposure_, "]");
  }

 private:
  static bool isDisplayExtension(const std::string& ext) { return ext == ".png" || ext == ".jpg" || ext == ".jpeg"; }

  float encode(float v) const { return gamma_ == -1.0f ? linearToSRGB(v) : std::pow(v, 1.0f / gamma_); }

  static float luminance(const float* rgb) { return 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2]; }

  void applyReinhard(Bitmap& image) const {
    const size_t pixels = size_t(image.width) * image.height;
    // Log-average luminance (eq. 1), with a small delta against black pixels.
    const double delta = 1e-4;
    double logSum = 0.0;
    float maxY = 0.0f;
    for (size_t i = 0; i < pixels; ++i) {
      float y = std::max(0.0f, luminance(&image.data[i * image.channels]));
      logSum += std::log(delta + y);
      maxY = std::max(maxY, y);
    }
    const double average = std::exp(logSum / double(std::max<size_t>(pixels, 1)));
    const double scale = key_ / average;
    const double white = std::max(1e-12, (1.0 - burn_) * maxY * scale);
    for (size_t i = 0; i < pixels; ++i) {
      float* rgb = &image.data[i * image.channels];
      float y = luminance(rgb);
      if (!(y > 0.0f)) {
        rgb[0] = rgb[1] = rgb[2] = 0.0f;
        continue;
      }
      double l = y * scale;
      double ld = l * (1.0 + l / (white * white)) / (1.0 + l);
      float ratio = float(ld / y);
      for (int c = 0; c < 3; ++c) rgb[c] *= ratio;
    }
  }

  std::string extension_ = ".png";
  bool reinhard_ = false;
  float gamma_, exposure_, key_, burn_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::LDRFilm, Film, "ldrfilm", "Mitsuba 0.6 low dynamic range film: tone mapped PNG or JPEG")
