#include <femto/render/path_depth.h>

#include <algorithm>
#include <limits>

namespace femto {
namespace {

constexpr int64_t IntMax = std::numeric_limits<int>::max();

}  // namespace

PathDepthSettings PathDepthSettings::read(const Properties& props, int defaultMaxDepth) {
  PathDepthSettings s;
  s.maxDepth =
      int(std::min(props.getInt("max_depth", defaultMaxDepth, -1, Properties::Unbounded, "-1: no limit"), IntMax));
  s.rrDepth = int(std::min(props.getInt("rr_depth", s.rrDepth, 1, Properties::Unbounded), IntMax));
  return s;
}

std::string PathDepthSettings::toString() const { return str("max_depth=", maxDepth, ", rr_depth=", rrDepth); }

}  // namespace femto
