#include <femto/render/transient_tile.h>

#include <algorithm>
#include <cmath>

#include <femto/render/scene.h>

namespace femto {
namespace {

void addScaled(float* dst, const Color3f& value, double share) {
  dst[0] += float(value.r * share);
  dst[1] += float(value.g * share);
  dst[2] += float(value.b * share);
}

}  // namespace

void TransientSampleRecorder::add(double opl, const Color3f& value) {
  if (opl >= deposit_.horizon()) return;  // NaN is kept, for valid() to refuse
  contributions_.push_back({opl, opl, value, false});
}

void TransientSampleRecorder::addInterval(double opl0, double opl1, const Color3f& value) {
  double lo = std::min(opl0, opl1), hi = std::max(opl0, opl1), horizon = deposit_.horizon();
  if (lo >= horizon) return;
  // The value is spread uniformly over [lo, hi]: keep the part before the horizon.
  if (hi > horizon) {
    contributions_.push_back({lo, horizon, value * float((horizon - lo) / (hi - lo)), true});
    return;
  }
  contributions_.push_back({opl0, opl1, value, true});
}

bool TransientSampleRecorder::valid(const Color3f& weight) const {
  for (const Contribution& c : contributions_)
    if (!(weight * c.value).isValid() || !std::isfinite(c.opl0) || !std::isfinite(c.opl1)) return false;
  return true;
}

void TransientSampleRecorder::commit(const Color3f& weight, float* bins, float* steady, float* before, float* after) {
  for (const Contribution& c : contributions_) {
    Color3f value = weight * c.value;
    if (value.isBlack()) continue;
    if (c.interval)
      deposit_.interval(c.opl0, c.opl1, shares_);
    else
      deposit_.point(c.opl0, shares_);
    for (size_t k = 0; k < shares_.weights.size(); ++k)
      addScaled(bins + (size_t(shares_.first) + k) * 3, value, shares_.weights[k]);
    addScaled(steady, value, 1.0);
    if (shares_.before > 0.0) addScaled(before, value, shares_.before);
    if (shares_.after > 0.0) addScaled(after, value, shares_.after);
  }
}

TransientTile::TransientTile(const Point2i& offset, const Point2i& size, const TransientRenderContext& context)
    : offset_(offset), size_(size), bins_(context.deposit.grid().bins), context_(context), recorder_(context.deposit) {
  const size_t pixels = size_t(size.x) * size_t(size.y);
  volume_.assign(pixels * bins_ * 3, 0.0f);
  steady_.assign(pixels * 3, 0.0f);
  before_.assign(pixels * 3, 0.0f);
  after_.assign(pixels * 3, 0.0f);
  weight_.assign(pixels, 0.0f);
}

bool TransientTile::addSample(const Point2i& pixel, const Point2f& pos, Sampler& sampler) {
  // Same sample order as SamplingIntegrator: aperture sample, then the integrator's.
  Ray ray;
  Color3f weight = context_.scene.sensor().sampleRay(pos, sampler.next2D(), ray);
  recorder_.clear();
  if (!weight.isBlack()) context_.integrator.sample(context_.scene, ray, sampler, recorder_);
  if (!recorder_.valid(weight)) return false;
  // The box pixel filter: the sample counts fully, and only, for its own
  // pixel; the transient film refuses wider filters.
  const int x = pixel.x - offset_.x, y = pixel.y - offset_.y;
  const size_t i = index(x, y);
  recorder_.commit(weight, binsOf(x, y), &steady_[i * 3], &before_[i * 3], &after_[i * 3]);
  weight_[i] += 1.0f;
  return true;
}

void TransientTile::normalize() {
  for (int y = 0; y < size_.y; ++y)
    for (int x = 0; x < size_.x; ++x) {
      const size_t i = index(x, y);
      // One weight for all quantities: the volume's bins then add up to the
      // steady value minus before and after, to float precision.
      const float scale = weight_[i] > 0.0f ? 1.0f / weight_[i] : 0.0f;
      float* b = binsOf(x, y);
      for (int k = 0; k < bins_ * 3; ++k) b[k] *= scale;
      for (int c = 0; c < 3; ++c) steady_[i * 3 + c] *= scale, before_[i * 3 + c] *= scale, after_[i * 3 + c] *= scale;
    }
}

}  // namespace femto
