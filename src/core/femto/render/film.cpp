#include <femto/render/film.h>

#include <femto/render/default_child.h>

namespace femto {

Film::Film(const Properties& props) : Film(props, "gaussian") {}

Film::Film(const Properties& props, const char* defaultFilter) : Film(props, defaultFilter, std::string()) {}

Film::Film(const Properties& props, const char* defaultFilter, const std::string& reservedFilterName) {
  constexpr int64_t MaxSize = 1 << 16;
  size_ = Point2i(int(props.getInt("width", 768, 1, MaxSize)), int(props.getInt("height", 576, 1, MaxSize)));
  cropOffset_ = Point2i(int(props.getInt("crop_offset_x", 0, 0, size_.x - 1)),
                        int(props.getInt("crop_offset_y", 0, 0, size_.y - 1)));
  cropSize_ = Point2i(int(props.getInt("crop_width", size_.x - cropOffset_.x, 1, size_.x - cropOffset_.x)),
                      int(props.getInt("crop_height", size_.y - cropOffset_.y, 1, size_.y - cropOffset_.y)));
  filter_ = nestedOrDefault<ReconstructionFilter>(props, ObjectKind::ReconstructionFilter, defaultFilter,
                                                  reservedFilterName);
}

Bitmap Film::developCrop(const ImageBlock& image) const {
  Bitmap bitmap(cropSize_.x, cropSize_.y, 3);
  for (int y = 0; y < cropSize_.y; ++y)
    for (int x = 0; x < cropSize_.x; ++x) {
      Color3f c = image.value(Point2i(cropOffset_.x + x, cropOffset_.y + y));
      float* px = bitmap.pixel(x, y);
      px[0] = c.r, px[1] = c.g, px[2] = c.b;
    }
  return bitmap;
}

void Film::writeExrWithPreview(const std::filesystem::path& path, const Bitmap& image) {
  std::filesystem::path exr = path, png = path;
  exr.replace_extension(".exr");
  png.replace_extension(".png");
  writeEXR(exr, image);
  writePNG(png, image);
}

}  // namespace femto
