#pragma once
// One tile of a transient render: per pixel the time-binned RGB sums
// (bins x 3 floats, the .npy's pixel layout), the steady RGB sum, the sums
// before/after the window, and the sample weight every one of them is later
// divided by. The recorder buffers one camera sample's contributions and
// commits them only if all are valid, so a bad sample is dropped whole, as the
// steady film does.
#include <vector>

#include <femto/render/render_loop.h>
#include <femto/render/time_deposit.h>
#include <femto/render/transient_integrator.h>

namespace femto {

class Scene;
class Sensor;

/// Records one camera sample's contributions for a transient film.
class TransientSampleRecorder final : public RadianceRecorder {
 public:
  explicit TransientSampleRecorder(const TimeDeposit& deposit) : deposit_(deposit) {}
  /// Contributions at or past the horizon are dropped (the part of an
  /// interval past it too), whether or not the integrator stops its paths
  /// there: the steady image and `after` then hold exactly the light arriving
  /// before the horizon, for any integrator.
  void add(double opl, const Color3f& value) override;
  void addInterval(double opl0, double opl1, const Color3f& value) override;
  double horizon() const override { return deposit_.horizon(); }
  const TimeGrid& timeGrid() const override { return deposit_.grid(); }

  void clear() { contributions_.clear(); }
  /// All values valid (finite, non-negative) after scaling by `weight`, all OPLs finite?
  bool valid(const Color3f& weight) const;
  /// Add `weight` x the contributions to one pixel: `bins` (bins x 3 floats),
  /// `steady`, `before`, `after` (RGB each).
  void commit(const Color3f& weight, float* bins, float* steady, float* before, float* after);

 private:
  struct Contribution {
    double opl0, opl1;
    Color3f value;
    bool interval;
  };
  const TimeDeposit& deposit_;
  std::vector<Contribution> contributions_;
  BinShares shares_;
};

/// Everything a transient tile needs to take samples.
struct TransientRenderContext {
  const Scene& scene;
  const TransientIntegrator& integrator;
  const TimeDeposit& deposit;
};

class TransientTile final : public TileAccumulator {
 public:
  TransientTile(const Point2i& offset, const Point2i& size, const TransientRenderContext& context);
  bool addSample(const Point2i& pixel, const Point2f& pos, Sampler& sampler) override;

  const Point2i& offset() const { return offset_; }
  const Point2i& size() const { return size_; }
  int bins() const { return bins_; }
  /// Divide every quantity of every pixel by the pixel's sample weight
  /// (pixels without samples become 0): the developed values.
  void normalize();
  /// Pixel (x, y) relative to the tile: bins x 3 floats; a tile row is contiguous.
  float* binsOf(int x, int y) { return &volume_[(size_t(y) * size_.x + x) * bins_ * 3]; }
  const float* row(int y) const { return &volume_[size_t(y) * size_.x * bins_ * 3]; }
  /// Steady, before and after RGB of pixel (x, y) relative to the tile.
  const float* steady(int x, int y) const { return &steady_[index(x, y) * 3]; }
  const float* before(int x, int y) const { return &before_[index(x, y) * 3]; }
  const float* after(int x, int y) const { return &after_[index(x, y) * 3]; }

 private:
  size_t index(int x, int y) const { return size_t(y) * size_.x + x; }
  Point2i offset_, size_;
  int bins_;
  const TransientRenderContext& context_;
  TransientSampleRecorder recorder_;
  std::vector<float> volume_, steady_, before_, after_, weight_;
};

}  // namespace femto
