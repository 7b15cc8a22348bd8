#pragma once
// The parameters of the transient_beams integrator (see the table in
// transient_beams.cpp), read and checked once; immutable afterwards. Errors
// name the scene file and line of the offending parameter.
#include <cstdint>

#include <femto/core/error.h>
#include <femto/core/properties.h>
#include <femto/math/bbox.h>

namespace femto::beams {

/// Which photon segments in media become beams.
enum class BeamStore {
  Single,  // only photons that have not scattered yet (straight from the emitter, through specular chains): single scattering
  All,     // every segment: all orders of scattering in media
};

struct BeamSettings {
  int passes = 1;
  int64_t photonCount = 100000;  // photons traced per pass
  float radius = 0.0f;           // beam kernel radius of pass 0 (0: derived from the scene size)
  float surfaceRadius = 0.0f;    // surface photon kernel radius of pass 0 (0: derived)
  float alpha = 0.7f;            // progressive radius reduction, in (0, 1]
  int maxDepth = -1;             // longest camera + photon path in segments (-1: no limit)
  int rrDepth = 5;               // photon segments before Russian roulette may end a photon
  BeamStore store = BeamStore::All;
  bool observerTime = true;      // the camera segment counts toward the OPL
  bool hideEmitters = false;     // emitters seen directly appear black
  SourceLocation location;       // the <integrator> element, for errors found at render time

  /// Read and validate every parameter (unknown ones are the loader's business).
  static BeamSettings parse(const Properties& props);

  /// Fill in the radii not given, as fractions of the scene's bounding-box
  /// diagonal; an error naming the integrator when the scene has no extent.
  BeamSettings resolved(const BoundingBox3f& sceneBounds) const;

  /// Kernel radii of pass `pass` (0-based). The beam estimate uses a 1D
  /// kernel, whose variance grows as 1/r: r_{i+1} = r_i (i + alpha) / (i + 1)
  /// (Jarosz, Nowrouzezahrai, Thomas, Sloan, Zwicker 2011, "Progressive Photon
  /// Beams", sec. 4). The surface estimate uses a 2D kernel (variance ~ 1/r^2):
  /// r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1) (Knaus and Zwicker 2011,
  /// "Progressive Photon Mapping: A Probabilistic Approach", eq. 20).
  float beamRadius(int pass) const;
  float surfaceRadiusOf(int pass) const;

  /// Does a path of `segments` segments (camera + photon) stay within max_depth?
  bool depthAllowed(int segments) const { return maxDepth < 0 || segments <= maxDepth; }
};

}  // namespace femto::beams
