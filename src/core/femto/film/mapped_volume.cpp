#include <femto/film/mapped_volume.h>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <femto/base/error.h>
#include <femto/film/npy_volume.h>

namespace femto {

MappedVolume::MappedVolume(void* mapping, size_t mappedBytes, const float* data, int height, int width, int bins)
    : mapping_(mapping), mappedBytes_(mappedBytes), data_(data), height_(height), width_(width), bins_(bins) {}

MappedVolume::MappedVolume(MappedVolume&& o) noexcept
    : mapping_(o.mapping_),
      mappedBytes_(o.mappedBytes_),
      data_(o.data_),
      height_(o.height_),
      width_(o.width_),
      bins_(o.bins_) {
  o.mapping_ = nullptr;
}

MappedVolume::~MappedVolume() {
  if (mapping_) ::munmap(mapping_, mappedBytes_);
}

MappedVolume MappedVolume::open(const std::filesystem::path& path) {
  // NpyVolume::open reads and checks the header and the file's size; the
  // mapping then covers exactly the header plus the data it promises.
  const NpyVolume volume = NpyVolume::open(path);
  // numpy and femto pad the header to a multiple of 16 or 64 bytes; a file
  // padded otherwise would put the floats off their alignment.
  if (volume.dataOffset() % alignof(float) != 0)
    throw Error(str("\"", path.string(), "\": its .npy header (", volume.dataOffset(),
                    " bytes) leaves the data unaligned; save it again with numpy"));
  const size_t bytes =
      size_t(volume.dataOffset()) + size_t(volume.height()) * volume.width() * volume.bins() * 3 * sizeof(float);
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw Error(str("cannot open \"", path.string(), "\": ", std::strerror(errno)));
  void* mapping = ::mmap(nullptr, bytes, PROT_READ, MAP_SHARED, fd, 0);
  const int mapError = errno;
  ::close(fd);  // the mapping keeps the file open
  if (mapping == MAP_FAILED) throw Error(str("cannot map \"", path.string(), "\": ", std::strerror(mapError)));
  // A frame touches one page per pixel, bins * 12 bytes apart; the kernel's
  // readahead would fetch up to a hundred kilobytes around each (the bins a
  // frame does not need), which made a frame of a 12.9 GB volume take a
  // minute instead of a fraction of a second (test MappedVolume.TwelveGigabyteVolumeOpensAtOnce).
  ::madvise(mapping, bytes, MADV_RANDOM);
  const float* data = reinterpret_cast<const float*>(static_cast<const char*>(mapping) + volume.dataOffset());
  return MappedVolume(mapping, bytes, data, volume.height(), volume.width(), volume.bins());
}

static size_t pageBytes() { return size_t(::sysconf(_SC_PAGESIZE)); }

size_t MappedVolume::mappedPages() const { return (mappedBytes_ + pageBytes() - 1) / pageBytes(); }

size_t MappedVolume::residentPages() const {
  std::vector<unsigned char> resident(mappedPages());
  if (::mincore(mapping_, mappedBytes_, resident.data()) != 0)
    throw Error(str("mincore on a mapped volume failed: ", std::strerror(errno)));
  size_t n = 0;
  for (unsigned char r : resident) n += r & 1u;
  return n;
}

std::vector<float> MappedVolume::frame(int bin) const {
  if (bin < 0 || bin >= bins_) throw Error(str("bin ", bin, " is outside the volume (bins 0 to ", bins_ - 1, ")"));
  std::vector<float> out(size_t(height_) * size_t(width_) * 3);
  float* o = out.data();
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x, o += 3) {
      const float* v = pixel(y, x) + size_t(bin) * 3;
      o[0] = v[0], o[1] = v[1], o[2] = v[2];
    }
  return out;
}

}  // namespace femto
