#pragma once
// Image files. OpenEXR for float data, PNG written with zlib (previews), and
// OpenImageIO, loaded on first use, for everything else (textures, JPEG, HDR). Writes go to a temporary file in the same folder
// and are renamed into place, so a reader never sees a half-written file.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace femto {

/// Interleaved float image, row-major, top row first.
struct Bitmap {
  int width = 0, height = 0, channels = 0;
  std::vector<float> data;

  Bitmap() = default;
  Bitmap(int w, int h, int c) : width(w), height(h), channels(c), data(size_t(w) * h * c, 0.0f) {}
  float* pixel(int x, int y) { return &data[(size_t(y) * width + x) * channels]; }
  const float* pixel(int x, int y) const { return &data[(size_t(y) * width + x) * channels]; }
};

/// Write RGB(A) or single-channel float data as OpenEXR (channels R,G,B[,A] or Y).
void writeEXR(const std::filesystem::path& path, const Bitmap& image);
/// Write any number of float channels under the given names (one per
/// channel, e.g. "dd.T", "nn.X"), for arbitrary output variables.
void writeEXR(const std::filesystem::path& path, const Bitmap& image, const std::vector<std::string>& channelNames);
/// Write an 8-bit sRGB PNG preview: linear value * 2^exposure, clamped, sRGB-encoded.
void writePNG(const std::filesystem::path& path, const Bitmap& image, float exposure = 0.0f);
/// What writePNG stores, before quantisation: linear value * 2^exposure,
/// sRGB-encoded (a 4th channel is coverage: only clamped).
Bitmap encodeSRGB(const Bitmap& image, float exposure);
/// What writeDisplayImage stores: display values clamped to [0, 1], 8 bits
/// (rounded to nearest), in the image's channel order.
std::vector<uint8_t> quantize8(const Bitmap& image);
/// Write display-encoded values in [0, 1] (already tone mapped and
/// gamma-encoded; clamped) as 8 bits per channel, in the format the
/// extension names (PNG, JPEG, ... as OpenImageIO writes them).
void writeDisplayImage(const std::filesystem::path& path, const Bitmap& image);
/// Write linear float data in the format the extension names, through
/// OpenImageIO (Radiance .hdr, TIFF, PFM, ...; OpenEXR has writeEXR).
void writeFloatImage(const std::filesystem::path& path, const Bitmap& image);
/// Read any image OpenImageIO can open (EXR, HDR, PNG, JPEG, ...), as float.
/// 8-bit sRGB inputs are returned as stored values (no linearisation).
Bitmap readImage(const std::filesystem::path& path);

/// How a file stored its values (what texture plugins need to decode them).
struct ImageFileInfo {
  /// Integer samples (8- or 16-bit: PNG, JPEG, ...) that carry sRGB gamma,
  /// i.e. the file does not declare itself linear. Float formats never do.
  bool srgbEncoded = false;
  int bitsPerSample = 32;
  /// The file's channel names, in the order of the data ("R", "nn.X", ...).
  std::vector<std::string> channelNames;
};
/// readImage that also reports how the file stored its values.
Bitmap readImage(const std::filesystem::path& path, ImageFileInfo& info);

/// Write `path` atomically: `writer` gets a temporary path in the same
/// directory; on success it is renamed onto `path`, on failure removed.
template <typename Writer>
void writeAtomically(const std::filesystem::path& path, Writer&& writer);

/// sRGB transfer function (IEC 61966-2-1) for one linear value in [0, 1].
float linearToSRGB(float v);
/// Its inverse: an sRGB-encoded value in [0, 1] to linear.
float srgbToLinear(float v);

}  // namespace femto

#include <femto/image/write_atomically.inl>
