#include <femto/image/image_io.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <dlfcn.h>
#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <exception>
#include <fstream>

#include <femto/base/error.h>
#include <femto/image/detail/image_module.h>

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

/// libfemto-oiio.so, from the folder this library was loaded from, on first
/// use (detail/image_module.h); a missing or broken module is an Error.
const detail::ImageModule& imageModule() {
  static const detail::ImageModule* module = [] {
    Dl_info self{};
    if (!dladdr(reinterpret_cast<void*>(&imageModule), &self) || !self.dli_fname)
      throw Error("cannot locate libfemto-core to load its OpenImageIO module");
    const std::filesystem::path file = std::filesystem::path(self.dli_fname).parent_path() / "libfemto-oiio.so";
    void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) throw Error(str("cannot load OpenImageIO support (", file.string(), "): ", dlerror()));
    auto entry = reinterpret_cast<const detail::ImageModule* (*)()>(dlsym(handle, "femto_image_module"));
    if (!entry) throw Error(str(file.string(), " has no femto_image_module: ", dlerror()));
    return entry();
  }();
  return *module;
}

/// Appends v as 4 bytes, most significant first (PNG's integers).
void appendBigEndian32(std::string& out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(char((v >> shift) & 0xff));
}

/// Appends one PNG chunk (length, type, data, CRC-32 of type and data).
void appendChunk(std::string& png, const char (&type)[5], const std::string& data) {
  appendBigEndian32(png, uint32_t(data.size()));
  const std::string body = std::string(type, 4) + data;
  png += body;
  appendBigEndian32(png, uint32_t(crc32(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(body.data()),
                                        uInt(body.size()))));
}

/// 8-bit grey or RGB samples as a PNG file (ISO/IEC 15948: IHDR, sRGB,
/// one zlib-compressed IDAT of unfiltered rows, IEND), written with zlib so
/// the previews every render writes need no OpenImageIO (image_module.h).
void writePngFile(const std::filesystem::path& file, const std::filesystem::path& shown, int width, int height,
                  int channels, const std::vector<uint8_t>& samples) {
  const uint8_t colorType = channels == 1 ? 0 : 2;
  std::string header;
  appendBigEndian32(header, uint32_t(width));
  appendBigEndian32(header, uint32_t(height));
  header += std::string{char(8), char(colorType), char(0), char(0), char(0)};  // depth, type, deflate, filter, no interlace
  const size_t row = size_t(width) * channels;
  std::string raw;
  raw.reserve((row + 1) * height);
  for (int y = 0; y < height; ++y) {
    raw.push_back(char(0));  // filter type 0: the row as it is
    raw.append(reinterpret_cast<const char*>(samples.data()) + y * row, row);
  }
  uLongf size = compressBound(uLong(raw.size()));
  std::string deflated(size, '\0');
  if (compress2(reinterpret_cast<Bytef*>(deflated.data()), &size, reinterpret_cast<const Bytef*>(raw.data()),
                uLong(raw.size()), Z_DEFAULT_COMPRESSION) != Z_OK)
    throw Error(str("cannot write \"", shown.string(), "\": zlib could not compress the image"));
  deflated.resize(size);
  std::string png("\x89PNG\r\n\x1a\n", 8);
  appendChunk(png, "IHDR", header);
  appendChunk(png, "sRGB", std::string(1, char(0)));  // sRGB-encoded, perceptual intent
  appendChunk(png, "IDAT", deflated);
  appendChunk(png, "IEND", "");
  std::ofstream out(file, std::ios::binary);
  out.write(png.data(), std::streamsize(png.size()));
  out.close();
  if (!out) throw Error(str("cannot write \"", shown.string(), "\": the file could not be written"));
}

bool isPng(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".png";
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
    // RGBA goes through OpenImageIO, which stores it unassociated as PNG asks (rare: films write RGB).
    if (isPng(path) && image.channels != 4) return writePngFile(tmp, path, image.width, image.height, image.channels, bytes);
    imageModule().write(tmp, path, image.width, image.height, image.channels, bytes.data(), false);
  });
}

void writeFloatImage(const std::filesystem::path& path, const Bitmap& image) {
  checkImage(path, image);
  writeAtomically(path, [&](const std::filesystem::path& tmp) {
    imageModule().write(tmp, path, image.width, image.height, image.channels, image.data.data(), true);
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
  return imageModule().read(path, info);
}

}  // namespace femto
