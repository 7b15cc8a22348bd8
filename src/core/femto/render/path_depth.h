#pragma once
// The depth and Russian-roulette parameters every path-building integrator
// takes (path, transient_path and its mitransient names, transient_beams),
// read once with one rule, as Mitsuba 3's MonteCarloIntegrator does:
//
// | name      | type    | default | meaning                                                     |
// |-----------|---------|---------|-------------------------------------------------------------|
// | max_depth | integer | -1      | longest path in segments (-1: no limit; 1: emitters seen directly, 2: direct illumination) |
// | rr_depth  | integer | 5       | depth from which Russian roulette may end paths (at least 1) |
//
// Depths beyond what an int holds mean "no limit" in practice and are
// clamped to INT_MAX.
#include <string>

#include <femto/core/properties.h>

namespace femto {

struct PathDepthSettings {
  int maxDepth = -1;  // longest path in segments; -1: no limit
  int rrDepth = 5;    // segments before Russian roulette may end a path

  /// Read max_depth (default `defaultMaxDepth`: mitransient's integrators
  /// use 6) and rr_depth; out of range values raise at their file:line.
  static PathDepthSettings read(const Properties& props, int defaultMaxDepth = -1);

  /// Does a path of `segments` segments stay within max_depth?
  bool depthAllowed(int segments) const { return maxDepth < 0 || segments <= maxDepth; }
  /// "max_depth=-1, rr_depth=5", for toString().
  std::string toString() const;
};

}  // namespace femto
