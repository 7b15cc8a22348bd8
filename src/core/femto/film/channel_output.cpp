#include <femto/film/channel_output.h>

#include <femto/base/error.h>
#include <femto/image/image_io.h>

namespace femto {

void developChannels(const ImageBlock& image, const Film& film, const std::vector<std::string>& channelNames,
                     std::filesystem::path path) {
  const int channels = int(channelNames.size());
  if (channels != image.channelCount())
    throw Error(str(channels, " channel names for an image of ", image.channelCount(), " channels"));
  Bitmap bitmap(film.cropSize().x, film.cropSize().y, channels);
  for (int y = 0; y < film.cropSize().y; ++y)
    for (int x = 0; x < film.cropSize().x; ++x)
      image.values(Point2i(film.cropOffset().x + x, film.cropOffset().y + y), bitmap.pixel(x, y));
  path.replace_extension(".exr");
  writeEXR(path, bitmap, channelNames);
}

}  // namespace femto
