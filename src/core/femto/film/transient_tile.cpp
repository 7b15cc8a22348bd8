#include <femto/film/transient_tile.h>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>

#include <femto/base/error.h>
#include <femto/base/thread_edges.h>
#include <femto/film/transient_film.h>
#include <femto/render/emitter.h>
#include <femto/render/film.h>
#include <femto/render/image_block.h>
#include <femto/render/rfilter.h>
#include <femto/render/sampler.h>
#include <femto/render/medium.h>
#include <femto/render/sensor.h>
#include <femto/render/scene.h>

namespace femto {
namespace {

void addScaled(float* dst, const Color3f& value, double share) {
  dst[0] += float(value.r * share);
  dst[1] += float(value.g * share);
  dst[2] += float(value.b * share);
}

}  // namespace

/// The OPL from the sensor to `ray`'s near-clip point (its mint, in the sensor's medium).
static double nearClipOrigin(const Scene& scene, const Ray& ray) {
  const Medium* medium = scene.sensor().medium();
  return double(ray.tmin) * (medium ? double(medium->eta()) : 1.0);
}

double largestNearClipOrigin(const Scene& scene) {
  // mint grows toward the film's edges (perspective: near_clip / cos theta);
  // a 9 x 9 grid of film positions (its corners and edges included) times
  // the aperture's corners and centre.
  const Sensor& sensor = scene.sensor();
  const Point2i size = sensor.film().cropSize();
  const Point2i offset = sensor.film().cropOffset();
  double largest = 0.0;
  constexpr int Grid = 8;
  for (int i = 0; i <= Grid; ++i)
    for (int j = 0; j <= Grid; ++j)
      for (Point2f aperture : {Point2f(0.5f, 0.5f), Point2f(0.0f, 0.0f), Point2f(1.0f, 0.0f), Point2f(0.0f, 1.0f),
                               Point2f(1.0f, 1.0f)}) {
        Point2f pos(float(offset.x) + float(size.x) * float(i) / Grid, float(offset.y) + float(size.y) * float(j) / Grid);
        Ray ray;
        if (sensor.sampleRay(pos, aperture, ray).isBlack()) continue;
        largest = std::max(largest, nearClipOrigin(scene, ray));
      }
  // A margin for positions between the grid's (where mint is not larger for
  // the cameras femto has; float rounding aside).
  return largest * (1.0 + 1e-5);
}

double pulsedHorizon(const TimeDeposit& deposit, const Scene& scene) {
  double earliest = 0.0;
  bool any = false;
  for (const auto& emitter : scene.emitters()) {
    earliest = any ? std::min(earliest, emitter->pulse().earliest()) : emitter->pulse().earliest();
    any = true;
  }
  return deposit.horizon() - earliest;
}

void TransientSampleRecorder::addPulsed(double opl0, double opl1, const Color3f& value, const EmissionPulse& pulse) {
  const double horizon = deposit_.horizon();
  double lo = std::min(opl0, opl1) - origin_, hi = std::max(opl0, opl1) - origin_;
  if (!pulse.isDelta()) {
    if (lo + pulse.earliest() >= horizon) return;  // NaN is kept, for valid() to refuse
    contributions_.push_back({lo, hi, value, pulse});
    hasSteps_ |= pulse.isContinuous();
    return;
  }
  lo += pulse.offset(), hi += pulse.offset();
  if (lo >= horizon) return;
  // The value is spread uniformly over [lo, hi]: keep the part before the horizon.
  if (hi > horizon) {
    contributions_.push_back({lo, horizon, value * float((horizon - lo) / (hi - lo)), EmissionPulse()});
    return;
  }
  contributions_.push_back({lo, hi, value, EmissionPulse()});
}

bool TransientSampleRecorder::valid(const Color3f& weight) const {
  for (const Contribution& c : contributions_)
    if (!(weight * c.value).isValid() || !std::isfinite(c.opl0) || !std::isfinite(c.opl1)) return false;
  return true;
}

void TransientSampleRecorder::commit(const Color3f& weight, float* bins, float* steady, float* before, float* after,
                                     float* steps) {
  for (const Contribution& c : contributions_) {
    Color3f value = weight * c.value;
    if (value.isBlack()) continue;
    deposit_.pulsed(c.opl0, c.opl1, c.pulse, shares_);
    for (size_t k = 0; k < shares_.weights.size(); ++k)
      addScaled(bins + (size_t(shares_.first) + k) * 3, value, shares_.weights[k]);
    if (shares_.stepFrom >= 0) addScaled(steps + size_t(shares_.stepFrom) * 3, value, 1.0);
    addScaled(steady, value, 1.0);
    if (shares_.before > 0.0) addScaled(before, value, shares_.before);
    if (shares_.after > 0.0) addScaled(after, value, shares_.after);
  }
}

namespace {

/// One camera sample at film position `pos`: its ray, the integrator's
/// contributions into `recorder` (cleared first), measured from the ray's
/// time origin. Returns the sensor's weight (black: no ray, nothing recorded).
Color3f recordCameraSample(const TransientRenderContext& context, const Point2f& pos, Sampler& sampler,
                           TransientSampleRecorder& recorder) {
  Ray ray;
  const Color3f weight = context.scene.sensor().sampleRay(pos, sampler.next2D(), ray);
  recorder.clear();
  if (context.nearClipOrigin) recorder.setOrigin(nearClipOrigin(context.scene, ray));
  if (!weight.isBlack()) context.integrator.sample(context.scene, ray, sampler, recorder);
  return weight;
}

/// Continuous pulses: add each step's whole value to every bin from its start
/// on (`bins` x 3 floats each; running sums in double, then once to float).
void addStepRuns(float* binValues, const float* steps, int bins) {
  double run[3] = {0.0, 0.0, 0.0};
  for (int k = 0; k < bins; ++k)
    for (int c = 0; c < 3; ++c) binValues[k * 3 + c] += float(run[c] += steps[k * 3 + c]);
}

}  // namespace

std::vector<double> pilotTimeProfile(const TransientRenderContext& context, uint64_t seed, int samples, int threads) {
  const Scene& scene = context.scene;
  const Sensor& sensor = scene.sensor();
  const Film& film = sensor.film();
  const int bins = context.deposit.grid().bins;
  const Point2i crop = film.cropSize(), offset = film.cropOffset();
  const uint64_t pixels = uint64_t(crop.x) * uint64_t(crop.y);
  // Fixed chunks of samples, each summed by one task, the chunks' sums added
  // in chunk order: the same bits on any number of threads.
  constexpr int Chunk = 256;
  const int chunks = pixels > 0 && samples > 0 ? (samples + Chunk - 1) / Chunk : 0;
  std::vector<std::vector<double>> chunkSums(static_cast<size_t>(chunks));
  auto traceChunk = [&](int c) {
    std::vector<float> sums(size_t(bins) * 3, 0.0f), steps(sums.size(), 0.0f);
    float steady[3] = {}, before[3] = {}, after[3] = {};
    TransientSampleRecorder recorder(context.deposit, pulsedHorizon(context.deposit, scene));
    std::unique_ptr<Sampler> sampler = sensor.sampler().clone();
    for (int k = c * Chunk; k < std::min(samples, (c + 1) * Chunk); ++k) {
      const uint64_t p = uint64_t(k) * pixels / uint64_t(samples);
      sampler->startPixel(seed, uint64_t(k));
      const Point2f jitter = sampler->next2D();
      const Point2f pos(float(offset.x + int(p % uint64_t(crop.x))) + jitter.x,
                        float(offset.y + int(p / uint64_t(crop.x))) + jitter.y);
      const Color3f weight = recordCameraSample(context, pos, *sampler, recorder);
      if (!weight.isBlack() && recorder.valid(weight))
        recorder.commit(weight, sums.data(), steady, before, after, steps.data());
    }
    addStepRuns(sums.data(), steps.data(), bins);
    std::vector<double>& profile = chunkSums[size_t(c)];
    profile.assign(size_t(bins), 0.0);
    for (int b = 0; b < bins; ++b)
      for (int ch = 0; ch < 3; ++ch) profile[size_t(b)] += double(sums[size_t(b) * 3 + ch]) / 3.0;
  };
  auto traceAll = [&] {
    ForkJoinEdges edges;
    tbb::parallel_for(0, chunks, edges.task(traceChunk));
    edges.join();
  };
  if (threads > 0) {
    tbb::task_arena arena(threads);
    executeInArena(arena, traceAll);
  } else
    traceAll();
  std::vector<double> profile(size_t(bins), 0.0);
  for (const std::vector<double>& chunk : chunkSums)
    for (int b = 0; b < bins; ++b) profile[size_t(b)] += chunk[size_t(b)];
  return profile;
}

TimeLevels pilotTimeLevels(const Scene& scene, const TransientFilm& film, const TransientIntegrator& integrator,
                           uint64_t seed, int threads) {
  const TimeGrid& window = film.timeGrid();
  const TimeGrid axis = TimeLevels::pilotAxis(window, TimeLevels::PilotBins);
  const TimeDeposit deposit(axis, TimeFilter::box());
  const TransientRenderContext context{scene, integrator, deposit,
                                       film.nearClipOrigin() && integrator.countsCameraSegment()};
  const int samples = TimeLevels::pilotSamples(double(film.cropSize().x) * double(film.cropSize().y) *
                                               double(scene.sensor().sampler().sampleCount()));
  return TimeLevels::fromProfile(pilotTimeProfile(context, seed, samples, threads), axis, window.start);
}

TransientTile::TransientTile(const Point2i& offset, const Point2i& size, const TransientRenderContext& context)
    : offset_(offset),
      size_(size),
      bins_(context.deposit.grid().bins),
      context_(context),
      recorder_(context.deposit, pulsedHorizon(context.deposit, context.scene)) {
  const ReconstructionFilter* filter = context.scene.sensor().film().filter();
  if (filter && filter->radius() > 0.5f) {
    filter_ = filter;
    border_ = filterBorder(filter);
  }
  stored_ = Point2i(size.x + 2 * border_, size.y + 2 * border_);
  const size_t pixels = size_t(stored_.x) * size_t(stored_.y);
  volume_.assign(pixels * bins_ * 3, 0.0f);
  steady_.assign(pixels * 3, 0.0f);
  before_.assign(pixels * 3, 0.0f);
  after_.assign(pixels * 3, 0.0f);
  weight_.assign(pixels, 0.0f);
}

bool TransientTile::addSample(const Point2i& pixel, const Point2f& pos, Sampler& sampler) {
  // Same sample order as SamplingIntegrator: aperture sample, then the integrator's.
  const Color3f weight = recordCameraSample(context_, pos, sampler, recorder_);
  if (!recorder_.valid(weight)) return false;
  if (recorder_.hasSteps() && steps_.empty()) steps_.assign(volume_.size(), 0.0f);
  if (border_ > 0) {
    // A wider filter: the sample's contributions go to every pixel of its
    // footprint (this tile and its border), weighted as ImageBlock weighs them.
    const FilterFootprint f = filterFootprint(filter_, pos.x - float(offset_.x - border_) - 0.5f,
                                              pos.y - float(offset_.y - border_) - 0.5f, stored_.x, stored_.y);
    for (int y = f.y0; y <= f.y1; ++y)
      for (int x = f.x0; x <= f.x1; ++x) {
        const float w = f.wx[x - f.x0] * f.wy[y - f.y0];
        const size_t i = size_t(y) * size_t(stored_.x) + size_t(x);
        recorder_.commit(weight * w, &volume_[i * size_t(bins_) * 3], &steady_[i * 3], &before_[i * 3],
                         &after_[i * 3], steps_.empty() ? nullptr : &steps_[i * size_t(bins_) * 3]);
        weight_[i] += w;
      }
    return true;
  }
  // Filters of radius 1/2 or less (the box): the sample counts fully, and
  // only, for its own pixel.
  const int x = pixel.x - offset_.x, y = pixel.y - offset_.y;
  const size_t i = index(x, y);
  recorder_.commit(weight, binsOf(x, y), &steady_[i * 3], &before_[i * 3], &after_[i * 3],
                   steps_.empty() ? nullptr : &steps_[i * size_t(bins_) * 3]);
  weight_[i] += 1.0f;
  return true;
}

void TransientTile::pack(std::vector<float>& out) const {
  out.clear();
  for (const std::vector<float>* part : {&volume_, &steady_, &before_, &after_, &weight_, &steps_})
    out.insert(out.end(), part->begin(), part->end());
}

void TransientTile::unpack(const float* data, size_t count) {
  const size_t fixed = volume_.size() + steady_.size() + before_.size() + after_.size() + weight_.size();
  // The steps travel only when the sender's samples made them (a continuous pulse).
  if (count != fixed && count != fixed + volume_.size())
    throw Error(str("a transient tile of ", fixed, " floats was sent ", count, " (not the same tile)"));
  steps_.assign(count == fixed ? 0 : volume_.size(), 0.0f);
  for (std::vector<float>* part : {&volume_, &steady_, &before_, &after_, &weight_, &steps_}) {
    std::copy(data, data + part->size(), part->begin());
    data += part->size();
  }
}

void TransientTile::addSteps() {
  if (steps_.empty()) return;
  for (size_t i = 0; i < weight_.size(); ++i)
    addStepRuns(&volume_[i * size_t(bins_) * 3], &steps_[i * size_t(bins_) * 3], bins_);
  steps_.clear();
}

void TransientTile::normalize() {
  addSteps();
  for (size_t i = 0; i < weight_.size(); ++i) {
    // One weight for all quantities: the volume's bins then add up to the
    // steady value minus before and after, to float precision.
    const float scale = weight_[i] > 0.0f ? 1.0f / weight_[i] : 0.0f;
    float* b = &volume_[i * size_t(bins_) * 3];
    for (int k = 0; k < bins_ * 3; ++k) b[k] *= scale;
    for (int c = 0; c < 3; ++c) steady_[i * 3 + c] *= scale, before_[i * 3 + c] *= scale, after_[i * 3 + c] *= scale;
  }
}

TransientTile::Raw TransientTile::takeRaw() {
  addSteps();
  Raw raw;
  raw.offset = offset_, raw.size = size_, raw.border = border_;
  raw.volume = std::move(volume_), raw.steady = std::move(steady_), raw.before = std::move(before_);
  raw.after = std::move(after_), raw.weight = std::move(weight_);
  return raw;
}

}  // namespace femto
