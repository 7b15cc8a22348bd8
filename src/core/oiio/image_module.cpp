// libfemto-oiio.so: image files through OpenImageIO (PNG, JPEG, HDR, TIFF, ...)
// for the core's image_io.cpp, which loads this module on first use
// (femto/image/detail/image_module.h says why it is a module of its own).
#include <OpenImageIO/imageio.h>

#include <femto/base/error.h>
#include <femto/image/detail/image_module.h>

namespace femto {
namespace {

void write(const std::string& file, const std::string& shown, int width, int height, int channels,
           const void* samples, bool floatSamples) {
  auto out = OIIO::ImageOutput::create(file);
  if (!out) throw Error(str("cannot write \"", shown, "\": ", OIIO::geterror()));
  const OIIO::TypeDesc type = floatSamples ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
  OIIO::ImageSpec spec(width, height, channels, type);
  spec.attribute("oiio:ColorSpace", floatSamples ? "Linear" : "sRGB");
  if (!out->open(file, spec) || !out->write_image(type, samples) || !out->close())
    throw Error(str("cannot write \"", shown, "\": ", out->geterror()));
}

Bitmap read(const std::string& file, ImageFileInfo& info) {
  auto in = OIIO::ImageInput::open(file);
  if (!in) throw Error(str("cannot read image \"", file, "\": ", OIIO::geterror()));
  const OIIO::ImageSpec& spec = in->spec();
  info.bitsPerSample = int(spec.format.size()) * 8;
  bool integer = spec.format.basetype == OIIO::TypeDesc::UINT8 || spec.format.basetype == OIIO::TypeDesc::UINT16;
  std::string colorSpace = spec.get_string_attribute("oiio:ColorSpace");
  bool declaredLinear = colorSpace == "Linear" || colorSpace == "linear" || colorSpace == "lin_srgb";
  info.srgbEncoded = integer && !declaredLinear;
  Bitmap image(spec.width, spec.height, spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.data.data()))
    throw Error(str("cannot read image \"", file, "\": ", in->geterror()));
  info.channelNames.assign(spec.channelnames.begin(), spec.channelnames.end());
  in->close();
  return image;
}

const detail::ImageModule Module{write, read};

}  // namespace
}  // namespace femto

extern "C" __attribute__((visibility("default"))) const femto::detail::ImageModule* femto_image_module() {
  return &femto::Module;
}
