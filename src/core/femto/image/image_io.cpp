#include <femto/image/image_io.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>

#include <femto/base/error.h>

namespace femto {
namespace {

std::vector<std::string> exrChannelNames(int channels) {
  switch (channels) {
    case 1: return {"Y"};
    case 3: return {"R", "G", "B"};
    case 4: return {"R", "G", "B", "A"};
    default: return {};
  }
}

void checkShape(const std::filesystem::path& path, const Bitmap& image) {
  if (image.width <= 0 || image.height <= 0 || image.data.size() != size_t(image.width) * image.height * image.channels)
    throw Error(str("cannot write \"", path.string(), "\": the image is empty or inconsistent (", image.width, "x",
                    image.height, "x", image.channels, ")"));
}

void checkImage(const std::filesystem::path& path, const Bitmap& image) {
  checkShape(path, image);
  if (image.channels != 1 && image.channels != 3 && image.channels != 4)
    throw Error(str("cannot write \"", path.string(), "\": ", image.channels, " channels (1, 3 or 4 are supported)"));
}

}  // namespace

float linearToSRGB(float v) {
  if (!(v > 0.0f)) return 0.0f;
  if (v >= 1.0f) return 1.0f;
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

void writeEXR(const std::filesystem::path& path, const Bitmap& image) {
  checkImage(path, image);
  writeEXR(path, image, exrChannelNames(image.channels));
}

void writeEXR(const std::filesystem::path& path, const Bitmap& image, const std::vector<std::string>& names) {
  checkShape(path, image);
  if (names.size() != size_t(image.channels))
    throw Error(str("cannot write \"", path.string(), "\": ", names.size(), " channel names for ", image.channels,
                    " channels"));
  writeAtomically(path, [&](const std::filesystem::path& tmp) {
    try {
      Imf::Header header(image.width, image.height);
      Imf::FrameBuffer frameBuffer;
      const size_t xStride = sizeof(float) * image.channels, yStride = xStride * image.width;
      for (int c = 0; c < image.channels; ++c) {
        header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
        // OpenEXR only reads through the pointer; its API is not const-correct.
        char* base = reinterpret_cast<char*>(const_cast<float*>(image.data.data() + c));
        frameBuffer.insert(names[c], Imf::Slice(Imf::FLOAT, base, xStride, yStride));
      }
      Imf::OutputFile file(tmp.c_str(), header);
      file.setFrameBuffer(frameBuffer);
      file.writePixels(image.height);
    } catch (const std::exception& e) {
      throw Error(str("cannot write \"", path.string(), "\": ", e.what()));
    }
  });
}

Bitmap encodeSRGB(const Bitmap& image, float exposure) {
  const float scale = std::exp2(exposure);
  Bitmap encoded = image;
  for (size_t i = 0; i < image.data.size(); ++i) {
    bool alpha = image.channels == 4 && i % 4 == 3;  // alpha is linear coverage, not a colour
    encoded.data[i] = alpha ? std::clamp(image.data[i], 0.0f, 1.0f) : linearToSRGB(image.data[i] * scale);
  }
  return encoded;
}

std::vector<uint8_t> quantize8(const Bitmap& image) {
  std::vector<uint8_t> bytes(image.data.size());
  for (size_t i = 0; i < image.data.size(); ++i) bytes[i] = uint8_t(std::clamp(image.data[i], 0.0f, 1.0f) * 255.0f + 0.5f);
  return bytes;
}

void writePNG(const std::filesystem::path& path, const Bitmap& image, float exposure) {
  checkImage(path, image);
  writeDisplayImage(path, encodeSRGB(image, exposure));
}

void writeDisplayImage(const std::filesystem::path& path, const Bitmap& image) {
  checkImage(path, image);
  std::vector<uint8_t> bytes = quantize8(image);
  writeAtomically(path, [&](const std::filesystem::path& tmp) {
    auto out = OIIO::ImageOutput::create(tmp.string());
    if (!out) throw Error(str("cannot write \"", path.string(), "\": ", OIIO::geterror()));
    OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    if (!out->open(tmp.string(), spec) || !out->write_image(OIIO::TypeDesc::UINT8, bytes.data()) || !out->close())
      throw Error(str("cannot write \"", path.string(), "\": ", out->geterror()));
  });
}

void writeFloatImage(const std::filesystem::path& path, const Bitmap& image) {
  checkImage(path, image);
  writeAtomically(path, [&](const std::filesystem::path& tmp) {
    auto out = OIIO::ImageOutput::create(tmp.string());
    if (!out) throw Error(str("cannot write \"", path.string(), "\": ", OIIO::geterror()));
    OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::FLOAT);
    spec.attribute("oiio:ColorSpace", "Linear");
    if (!out->open(tmp.string(), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, image.data.data()) || !out->close())
      throw Error(str("cannot write \"", path.string(), "\": ", out->geterror()));
  });
}

float srgbToLinear(float v) {
  if (!(v > 0.0f)) return 0.0f;
  if (v >= 1.0f) return 1.0f;
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

Bitmap readImage(const std::filesystem::path& path) {
  ImageFileInfo info;
  return readImage(path, info);
}

Bitmap readImage(const std::filesystem::path& path, ImageFileInfo& info) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw Error(str("cannot read image \"", path.string(), "\": ", OIIO::geterror()));
  const OIIO::ImageSpec& spec = in->spec();
  info.bitsPerSample = int(spec.format.size()) * 8;
  bool integer = spec.format.basetype == OIIO::TypeDesc::UINT8 || spec.format.basetype == OIIO::TypeDesc::UINT16;
  std::string colorSpace = spec.get_string_attribute("oiio:ColorSpace");
  bool declaredLinear = colorSpace == "Linear" || colorSpace == "linear" || colorSpace == "lin_srgb";
  info.srgbEncoded = integer && !declaredLinear;
  Bitmap image(spec.width, spec.height, spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.data.data()))
    throw Error(str("cannot read image \"", path.string(), "\": ", in->geterror()));
  info.channelNames.assign(spec.channelnames.begin(), spec.channelnames.end());
  in->close();
  return image;
}

}  // namespace femto
