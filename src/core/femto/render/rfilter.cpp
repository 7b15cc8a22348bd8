#include <femto/render/rfilter.h>

#include <cmath>

#include <femto/base/error.h>

namespace femto {

void ReconstructionFilter::setRadius(float r) {
  if (!(r > 0.0f) || !std::isfinite(r)) throw Error(str("reconstruction filter radius must be positive, got ", r));
  radius_ = r;
}

void ReconstructionFilter::buildTable() {
  for (int i = 0; i <= TableSize; ++i) table_[i] = eval(radius_ * float(i) / float(TableSize));
  scale_ = float(TableSize) / radius_;
}

void ReconstructionFilter::initRadiusAndTable(const Properties& props, float def) {
  setRadius(props.getFloat("radius", def, Range::positive()));
  buildTable();
}

float ReconstructionFilter::evalTabulated(float x) const {
  // Nearest table entry; the film's per-pixel weight normalisation makes the
  // small quantisation error harmless (Mitsuba does the same).
  float pos = std::abs(x) * scale_ + 0.5f;
  if (!(pos < float(TableSize + 1))) return 0.0f;
  return table_[size_t(pos)];
}

}  // namespace femto
