#pragma once
// Film: image size, crop window, reconstruction filter and how the result is
// written. Accumulation happens in ImageBlocks owned by the render loop.
#include <filesystem>
#include <memory>

#include <femto/core/object.h>
#include <femto/core/properties.h>
#include <femto/image/image_io.h>
#include <femto/math/vector.h>
#include <femto/render/image_block.h>
#include <femto/render/rfilter.h>
#include <femto/time/time_deposit.h>

namespace femto {

class Film : public Object {
 public:
  /// Reads width/height (default 768x576), crop_offset_x/y, crop_width/height
  /// and a nested <rfilter> (default: gaussian, as Mitsuba).
  explicit Film(const Properties& props);
  ObjectKind kind() const override { return ObjectKind::Film; }

  const Point2i& size() const { return size_; }
  const Point2i& cropOffset() const { return cropOffset_; }
  const Point2i& cropSize() const { return cropSize_; }
  const ReconstructionFilter* filter() const { return filter_.get(); }

  /// Write the developed crop window to `path` (the film chooses the format
  /// and writes previews beside it). Writes are atomic.
  virtual void develop(const ImageBlock& image, const std::filesystem::path& path) const = 0;
  /// Default output file extension (".exr").
  virtual std::string defaultExtension() const { return ".exr"; }
  /// Called before rendering with the output path: refuse (femto::Error) an
  /// output the film cannot write, so no render is lost to a bad name.
  virtual void checkOutputPath(const std::filesystem::path&) const {}
  /// Does the film have a time axis (only transient integrators can fill it)?
  virtual bool timeResolved() const { return false; }
  /// mitransient gives the time filter to the integrator (temporal_filter);
  /// the scene hands it to the film when it is built. Steady films have no
  /// time axis and ignore it; see TransientFilm.
  virtual void useIntegratorTimeFilter(const TimeFilter&, const SourceLocation&) {}

  /// The developed crop window of `image` (sum / weight per pixel), RGB.
  Bitmap developCrop(const ImageBlock& image) const;
  /// Write `image` as linear float32 OpenEXR at `path` with extension .exr
  /// and an 8-bit sRGB PNG preview beside it (same stem, .png).
  static void writeExrWithPreview(const std::filesystem::path& path, const Bitmap& image);

 protected:
  /// As Film(props), with plugin `defaultFilter` when no <rfilter> is nested.
  Film(const Properties& props, const char* defaultFilter);
  /// As above, leaving the nested <rfilter name="`reservedFilterName`"> to the
  /// subclass (Mitsuba 2's streak film: its time filter "tfilter").
  Film(const Properties& props, const char* defaultFilter, const std::string& reservedFilterName);

 private:
  Point2i size_, cropOffset_, cropSize_;
  std::shared_ptr<ReconstructionFilter> filter_;
};

}  // namespace femto
