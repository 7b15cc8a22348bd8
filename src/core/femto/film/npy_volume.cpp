#include <femto/film/npy_volume.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>
#include <string>

#include <femto/base/error.h>

namespace femto {
namespace {

constexpr char Magic[] = "\x93NUMPY";
constexpr size_t MagicSize = 6;
constexpr size_t Alignment = 64;  // numpy pads headers so the data starts 64-byte aligned

[[noreturn]] void systemError(const std::filesystem::path& path, const char* what) {
  throw Error(str("cannot ", what, " \"", path.string(), "\": ", std::strerror(errno)));
}

/// pwrite/pread until all bytes moved (they may transfer less than asked).
template <typename Io, typename Ptr>
void transferAll(Io io, int fd, Ptr data, size_t bytes, uint64_t offset, const std::filesystem::path& path,
                 const char* what) {
  while (bytes > 0) {
    ssize_t n = io(fd, data, bytes, off_t(offset));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = EIO;
      systemError(path, what);
    }
    data += n, bytes -= size_t(n), offset += uint64_t(n);
  }
}

}  // namespace

std::vector<char> npyHeader(const std::vector<int64_t>& shape) {
  std::ostringstream dict;
  dict << "{'descr': '<f4', 'fortran_order': False, 'shape': (";
  for (int64_t n : shape) dict << n << ", ";
  dict << "), }";
  std::string text = dict.str();
  size_t total = MagicSize + 4 + text.size() + 1;  // magic, version, length, dict, '\n'
  text.append((Alignment - total % Alignment) % Alignment, ' ');
  text += '\n';
  std::vector<char> header(Magic, Magic + MagicSize);
  header.push_back(1), header.push_back(0);  // version 1.0
  header.push_back(char(text.size() & 0xff)), header.push_back(char(text.size() >> 8));
  header.insert(header.end(), text.begin(), text.end());
  return header;
}

NpyVolume::NpyVolume(std::filesystem::path path, int fd, int height, int width, int bins, uint64_t dataOffset)
    : path_(std::move(path)), fd_(fd), height_(height), width_(width), bins_(bins), dataOffset_(dataOffset) {}

NpyVolume::NpyVolume(NpyVolume&& o) noexcept
    : path_(std::move(o.path_)), fd_(o.fd_), height_(o.height_), width_(o.width_), bins_(o.bins_),
      dataOffset_(o.dataOffset_) {
  o.fd_ = -1;
}

NpyVolume::~NpyVolume() {
  if (fd_ >= 0) ::close(fd_);
}

NpyVolume NpyVolume::create(const std::filesystem::path& path, int height, int width, int bins) {
  std::vector<char> header = npyHeader({height, width, bins, 3});
  int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) systemError(path, "create");
  NpyVolume volume(path, fd, height, width, bins, header.size());
  transferAll(::pwrite, fd, header.data(), header.size(), 0, path, "write");
  uint64_t total = volume.offsetOf(height, 0);
  if (::ftruncate(fd, off_t(total)) != 0) systemError(path, "resize");
  return volume;
}

NpyVolume NpyVolume::open(const std::filesystem::path& path, bool writable) {
  int fd = ::open(path.c_str(), (writable ? O_RDWR : O_RDONLY) | O_CLOEXEC);
  if (fd < 0) systemError(path, "open");
  NpyVolume volume(path, fd, 0, 0, 0, 0);  // owns fd from here (closed on throw)
  char prefix[MagicSize + 4];
  struct stat info {};
  if (::fstat(fd, &info) != 0) systemError(path, "read");
  const uint64_t fileSize = uint64_t(info.st_size);
  if (fileSize < sizeof(prefix)) throw Error(str("\"", path.string(), "\" is not a version 1 .npy file"));
  transferAll(::pread, fd, prefix, sizeof(prefix), 0, path, "read");
  if (std::memcmp(prefix, Magic, MagicSize) != 0 || prefix[6] != 1)
    throw Error(str("\"", path.string(), "\" is not a version 1 .npy file"));
  size_t length = size_t(uint8_t(prefix[8])) | (size_t(uint8_t(prefix[9])) << 8);
  if (fileSize < sizeof(prefix) + length)
    throw Error(str("\"", path.string(), "\" is truncated: its .npy header is cut short"));
  std::string text(length, '\0');
  transferAll(::pread, fd, text.data(), length, sizeof(prefix), path, "read");
  long h = 0, w = 0, b = 0, c = 0;
  size_t shape = text.find("'shape': (");
  if (text.find("'descr': '<f4'") == std::string::npos || text.find("'fortran_order': False") == std::string::npos ||
      shape == std::string::npos ||
      std::sscanf(text.c_str() + shape, "'shape': (%ld, %ld, %ld, %ld", &h, &w, &b, &c) != 4 || c != 3 ||
      h <= 0 || w <= 0 || b <= 0 || h > (1 << 20) || w > (1 << 20) || b > (1 << 20))
    throw Error(str("\"", path.string(), "\" is not a float32 C-order (height, width, bins, 3) volume (its header: ",
                    text.substr(0, text.find('}') + 1), ")"));
  volume.height_ = int(h), volume.width_ = int(w), volume.bins_ = int(b);
  volume.dataOffset_ = sizeof(prefix) + length;
  // A volume cut short (a copy that failed, a render killed hard) would read
  // past its end: say so at once rather than at some pixel.
  const uint64_t expected = volume.offsetOf(int(h), 0);
  if (fileSize < expected)
    throw Error(str("\"", path.string(), "\" is truncated: a (", h, ", ", w, ", ", b, ", 3) volume needs ", expected,
                    " bytes, the file has ", fileSize));
  return volume;
}

uint64_t NpyVolume::offsetOf(int y, int x) const {
  return dataOffset_ + ((uint64_t(y) * uint64_t(width_) + uint64_t(x)) * uint64_t(bins_) * 3) * sizeof(float);
}

void NpyVolume::writePixels(int y, int x, int count, const float* data) {
  size_t bytes = size_t(count) * size_t(bins_) * 3 * sizeof(float);
  transferAll(::pwrite, fd_, reinterpret_cast<const char*>(data), bytes, offsetOf(y, x), path_, "write");
}

void NpyVolume::readPixels(int y, int x, int count, float* data) const {
  size_t bytes = size_t(count) * size_t(bins_) * 3 * sizeof(float);
  transferAll(::pread, fd_, reinterpret_cast<char*>(data), bytes, offsetOf(y, x), path_, "read");
}

void NpyVolume::readBins(int y, int x, int bin, int count, float* data) const {
  size_t bytes = size_t(count) * 3 * sizeof(float);
  uint64_t offset = offsetOf(y, x) + uint64_t(bin) * 3 * sizeof(float);
  transferAll(::pread, fd_, reinterpret_cast<char*>(data), bytes, offset, path_, "read");
}

}  // namespace femto
