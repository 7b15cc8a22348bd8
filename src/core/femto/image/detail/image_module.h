// The OpenImageIO side of image_io.cpp, kept out of libfemto-core: OpenImageIO
// pulls ~260 shared libraries whose symbol lookups cost every femto process
// ~0.35 CPU s at start-up, though most renders write only EXR and their PNG
// preview (written with zlib, image_io.cpp). libfemto-oiio.so (src/core/oiio/) implements this table; the core
// loads it from its own folder the first time an image goes through it (the
// module links nothing of the core).
#pragma once

#include <string>

#include <femto/image/image_io.h>

namespace femto::detail {

struct ImageModule {
  /// Writes width x height x channels samples to `file` (its extension names
  /// the format; `shown` is the name errors give): 8-bit sRGB-tagged bytes,
  /// or linear floats when `floatSamples`. Throws Error.
  void (*write)(const std::string& file, const std::string& shown, int width, int height, int channels,
                const void* samples, bool floatSamples);
  /// Reads any image OpenImageIO opens, as float; fills `info`. Throws Error.
  Bitmap (*read)(const std::string& file, ImageFileInfo& info);
};

}  // namespace femto::detail

/// The module's one entry point (C linkage: found by dlsym).
extern "C" const femto::detail::ImageModule* femto_image_module();
