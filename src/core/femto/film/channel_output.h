#pragma once
// Writing images of arbitrary named channels (the aov and moment
// integrators): the film gives size, crop window and filter; the image is
// developed from an ImageBlock of any channel count into one OpenEXR file.
#include <filesystem>
#include <string>
#include <vector>

#include <femto/render/film.h>
#include <femto/render/image_block.h>

namespace femto {

/// Develop the film's crop window of `image` (channelNames.size() channels)
/// and write it as OpenEXR to `path` with its extension replaced by ".exr".
void developChannels(const ImageBlock& image, const Film& film, const std::vector<std::string>& channelNames,
                     std::filesystem::path path);

}  // namespace femto
