// High dynamic range film: develops the crop window into the format the
// output's extension names: a linear RGB OpenEXR image (32-bit float) with an
// 8-bit sRGB PNG preview beside it (.exr, the default), 8-bit sRGB PNG or
// JPEG (.png, .jpg), or linear float Radiance HDR, TIFF or PFM (.hdr, .tif,
// .pfm); any other extension is refused before rendering. Mitsuba's usual
// hdrfilm parameters are read so that real scenes load in strict mode; the
// ones femto cannot honour produce a warning.
//
// | name               | type    | default   | meaning                                                       |
// |--------------------|---------|-----------|---------------------------------------------------------------|
// | width, height      | integer | 768, 576  | film size in pixels                                           |
// | crop_offset_x/y    | integer | 0         | top-left corner of the rendered window                        |
// | crop_width/height  | integer | full film | size of the rendered window                                   |
// | file_format        | string  | "openexr" | only OpenEXR is written (others: warning)                     |
// | pixel_format       | string  | "rgb"     | rgb (rgba, luminance, ...: warning, RGB is written)           |
// | component_format   | string  | "float16" | EXR channels are always float32 (any value accepted)          |
// | banner             | boolean | false     | Mitsuba 0.x banner overlay: ignored                           |
// | high_quality_edges | boolean | false     | also sample outside the crop window: not supported (warning)  |
// | sample_border      | boolean | false     | Mitsuba 3 name of high_quality_edges                          |
// | (nested rfilter)   | rfilter | gaussian  | pixel reconstruction filter                                   |
#include <cctype>

#include <femto/core/log.h>
#include <femto/image/image_io.h>
#include <femto/core/plugin.h>
#include <femto/render/film.h>

namespace femto {

class HDRFilm final : public Film {
 public:
  explicit HDRFilm(const Properties& props) : Film(props) {
    std::string fileFormat = props.getString("file_format", "openexr");
    if (fileFormat != "openexr" && fileFormat != "exr")
      warnUnsupported(props, "file_format", str("\"", fileFormat, "\" is not supported; writing OpenEXR"));
    std::string pixelFormat = props.getString("pixel_format", "rgb");
    if (pixelFormat != "rgb")
      warnUnsupported(props, "pixel_format", str("\"", pixelFormat, "\" is not supported; writing RGB"));
    props.getString("component_format", "float16");  // float32 is always written: more precise than asked
    props.getBool("banner", false);
    for (const char* name : {"high_quality_edges", "sample_border"})
      if (props.getBool(name, false))
        warnUnsupported(props, name, "sampling beyond the crop window is not supported; edges use only inner samples");
  }

  /// The format the output's extension names: .exr (and no extension) is
  /// linear float32 OpenEXR with an sRGB PNG preview beside it; .png and
  /// .jpg/.jpeg are 8-bit sRGB; .hdr, .tif/.tiff and .pfm are linear float.
  void develop(const ImageBlock& image, const std::filesystem::path& path) const override {
    Bitmap developed = developCrop(image);
    switch (formatOf(path)) {
      case Format::Exr: writeExrWithPreview(path, developed); break;
      case Format::Display: writePNG(path, developed); break;
      case Format::Float: writeFloatImage(path, developed); break;
    }
  }

  void checkOutputPath(const std::filesystem::path& path) const override { formatOf(path); }

  std::string toString() const override {
    return str("HDRFilm[size=", size().x, "x", size().y, ", crop=", cropSize().x, "x", cropSize().y, "+", cropOffset().x,
               "+", cropOffset().y, "]");
  }

 private:
  enum class Format { Exr, Display, Float };

  static Format formatOf(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext.empty() || ext == ".exr") return Format::Exr;
    if (ext == ".png" || ext == ".jpg" || ext == ".jpeg") return Format::Display;
    if (ext == ".hdr" || ext == ".tif" || ext == ".tiff" || ext == ".pfm") return Format::Float;
    throw Error(str("cannot write \"", path.string(), "\": hdrfilm writes .exr (with a .png preview), .png, .jpg, "
                    ".hdr, .tif or .pfm, not \"", ext, "\""));
  }

  static void warnUnsupported(const Properties& props, const std::string& name, const std::string& message) {
    SourceLocation where = props.location(name);
    logWarn(where.known() ? where.toString() + ": " : std::string(), "hdrfilm parameter \"", name, "\": ", message);
  }
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::HDRFilm, Film, "hdrfilm", "linear RGB OpenEXR film with PNG preview")
