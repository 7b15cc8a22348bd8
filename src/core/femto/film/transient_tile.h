#pragma once
// One tile of a transient render: per pixel the time-binned RGB sums
// (bins x 3 floats, the .npy's pixel layout), the steady RGB sum, the sums
// before/after the window, and the sample weight every one of them is later
// divided by. The recorder buffers one camera sample's contributions and
// commits them only if all are valid, so a bad sample is dropped whole, as the
// steady film does.
#include <vector>

#include <femto/loop/render_loop.h>
#include <femto/render/transient_integrator.h>
#include <femto/time/time_deposit.h>
#include <femto/time/time_levels.h>

namespace femto {

class Scene;
class Sensor;
class TransientFilm;

/// The recorder horizon for a scene: the deposit's horizon minus the
/// earliest offset of any emitter's pulse (a gaussian pulse can make light
/// arrive before a path's Dirac OPL, a delayed one after it).
double pulsedHorizon(const TimeDeposit& deposit, const Scene& scene);

/// Records one camera sample's contributions for a transient film.
class TransientSampleRecorder final : public RadianceRecorder {
 public:
  /// `horizon`: see pulsedHorizon (default: the deposit's, for Dirac pulses at 0).
  explicit TransientSampleRecorder(const TimeDeposit& deposit) : TransientSampleRecorder(deposit, deposit.horizon()) {}
  TransientSampleRecorder(const TimeDeposit& deposit, double horizon) : deposit_(deposit), horizon_(horizon) {}
  /// Contributions arriving at or past the deposit's horizon are dropped (the
  /// part of an interval past it too), whether or not the integrator stops its
  /// paths there: the steady image and `after` then hold exactly the light
  /// arriving before the horizon, for any integrator. A non-delta pulse is
  /// dropped when even its earliest emission arrives past it, else kept whole.
  void add(double opl, const Color3f& value) override { addPulsed(opl, opl, value, EmissionPulse()); }
  void addInterval(double opl0, double opl1, const Color3f& value) override {
    addPulsed(opl0, opl1, value, EmissionPulse());
  }
  void addPulsed(double opl0, double opl1, const Color3f& value, const EmissionPulse& pulse) override;
  /// The OPL this sample's contributions are measured from (the film's time
  /// origin on this camera ray, TransientFilm::nearClipOrigin): each is
  /// deposited at its OPL minus `origin`, and horizon() and timeGrid() are
  /// given in the integrator's OPL (the grid's start and the horizon plus `origin`).
  void setOrigin(double origin) {
    origin_ = origin;
    shiftedGrid_ = deposit_.grid();
    shiftedGrid_.start += origin;
  }
  double horizon() const override { return horizon_ + origin_; }
  const TimeGrid& timeGrid() const override { return origin_ == 0.0 ? deposit_.grid() : shiftedGrid_; }

  void clear() { contributions_.clear(), hasSteps_ = false; }
  /// All values valid (finite, non-negative) after scaling by `weight`, all OPLs finite?
  bool valid(const Color3f& weight) const;
  /// Does any contribution come from a continuous pulse (commit needs `steps`)?
  bool hasSteps() const { return hasSteps_; }
  /// Add `weight` x the contributions to one pixel: `bins` (bins x 3 floats),
  /// `steady`, `before`, `after` (RGB each). Continuous pulses add their
  /// whole value to every bin from some bin on: that is recorded once, in
  /// `steps` (bins x 3 floats, the derivative of those runs; may be null when
  /// !hasSteps()), and prefix-summed when the tile is done.
  void commit(const Color3f& weight, float* bins, float* steady, float* before, float* after, float* steps = nullptr);

 private:
  struct Contribution {
    double opl0, opl1;  // equal: a point
    Color3f value;
    EmissionPulse pulse;
  };
  const TimeDeposit& deposit_;
  double horizon_;
  double origin_ = 0.0;
  TimeGrid shiftedGrid_;
  std::vector<Contribution> contributions_;
  bool hasSteps_ = false;
  BinShares shares_;
};

/// Everything a transient tile needs to take samples.
class ReconstructionFilter;

struct TransientRenderContext {
  const Scene& scene;
  const TransientIntegrator& integrator;
  const TimeDeposit& deposit;
  /// OPL 0 at each camera ray's near-clip point (mitransient's films) when
  /// the integrator counts the camera segment.
  bool nearClipOrigin = false;
};

/// The largest near-clip OPL offset of any camera ray of `scene`'s sensor
/// (what a near-clip time origin adds to the horizon an integrator sees):
/// the near-clip distance along the ray times the index of the sensor's
/// medium, maximised over the film's corners, edges and aperture.
double largestNearClipOrigin(const Scene& scene);

/// The film's time profile from `samples` camera samples spread evenly over
/// the crop window (a pilot, before a render): per bin the mean over RGB of
/// the samples' summed contributions, as the film would bin them (origin,
/// time filter, pulses). Each sample restarts a clone of the sensor's sampler
/// from (`seed`, its index), so the profile depends on nothing else (traced
/// in parallel on `threads` threads, 0: all, in chunks summed in order: the
/// same on any thread count).
std::vector<double> pilotTimeProfile(const TransientRenderContext& context, uint64_t seed, int samples,
                                     int threads = 0);

/// time_splitting's levels (time/time_levels.h) for a render of `film` by
/// `integrator`: pilotTimeProfile on TimeLevels::pilotAxis of the film's
/// window, with TimeLevels::pilotSamples of one pass's camera samples, the
/// film's time origin where the integrator counts the camera segment. Empty
/// when the profile holds no light.
TimeLevels pilotTimeLevels(const Scene& scene, const TransientFilm& film, const TransientIntegrator& integrator,
                           uint64_t seed, int threads);

class TransientTile final : public TileAccumulator {
 public:
  TransientTile(const Point2i& offset, const Point2i& size, const TransientRenderContext& context);
  bool addSample(const Point2i& pixel, const Point2f& pos, Sampler& sampler) override;
  /// The raw sums (volume, steady, before, after, weights, then the steps
  /// when a continuous pulse made them), not yet normalized.
  void pack(std::vector<float>& out) const override;
  void unpack(const float* data, size_t count) override;

  /// Memory per pixel at most: the bins and, for continuous pulses, their
  /// step derivative (bins x 3 floats each), plus the RGB sums and weight.
  static double bytesPerPixel(int bins) { return (2.0 * 3.0 * double(bins) + 10.0) * sizeof(float); }

  const Point2i& offset() const { return offset_; }
  const Point2i& size() const { return size_; }
  int bins() const { return bins_; }
  /// Add the running sums of the continuous-pulse steps to the bins, then
  /// divide every quantity of every pixel by the pixel's sample weight
  /// (pixels without samples become 0): the developed values.
  void normalize();
  /// Pixels a sample of this tile reaches beyond it: 0 for filters of radius
  /// 1/2 or less (a sample counts for its own pixel only), else
  /// ceil(radius - 1/2); the tile then stores that border around itself, and
  /// neighbouring tiles' sums meet there (TransientOutput merges them).
  int border() const { return border_; }
  /// The raw sums of a bordered tile, moved out (the steps already added):
  /// per stored pixel (size + 2 border, row-major) bins x 3, RGB x 3 and the
  /// filter weight.
  struct Raw {
    Point2i offset, size;
    int border = 0;
    std::vector<float> volume, steady, before, after, weight;
  };
  Raw takeRaw();
  /// Pixel (x, y) relative to the tile (the border at -border..-1 and size..):
  /// bins x 3 floats; a tile row is contiguous.
  float* binsOf(int x, int y) { return &volume_[index(x, y) * bins_ * 3]; }
  const float* row(int y) const { return &volume_[index(0, y) * bins_ * 3]; }
  /// Steady, before and after RGB of pixel (x, y) relative to the tile.
  const float* steady(int x, int y) const { return &steady_[index(x, y) * 3]; }
  const float* before(int x, int y) const { return &before_[index(x, y) * 3]; }
  const float* after(int x, int y) const { return &after_[index(x, y) * 3]; }

 private:
  size_t index(int x, int y) const { return size_t(y + border_) * size_t(stored_.x) + size_t(x + border_); }
  void addSteps();
  Point2i offset_, size_;
  int bins_;
  int border_ = 0;
  Point2i stored_;  // size + 2 border
  const ReconstructionFilter* filter_ = nullptr;
  const TransientRenderContext& context_;
  TransientSampleRecorder recorder_;
  std::vector<float> volume_, steady_, before_, after_, weight_;
  std::vector<float> steps_;  // continuous-pulse step derivative (bins x 3 per pixel), allocated on first use
};

}  // namespace femto
