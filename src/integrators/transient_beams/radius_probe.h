#pragma once
// Probe segments for the derived beam radius (radius_rule.h): camera rays
// through an even grid of film positions, followed straight through
// index-matched boundaries (as camera paths are), cut into their pieces
// inside media. They stand for the camera segments that will gather beams:
// the density bound counts beams near them, the boundary bound takes their
// mean length. Specular chains are not followed (a view of a medium only
// through a mirror gives no probes; the rule then falls back, beam_settings.h).
#include <vector>

#include <transient_beams/radius_rule.h>

namespace femto {
class PCG32;
class Scene;
}  // namespace femto

namespace femto::beams {

/// One film position (pixel units) in each of grid x grid cells of the
/// crop window, row by row: the cell centres, or, with `jitter`, a point
/// drawn from it in each cell. Shared by the beams' and the surfaces' probes.
std::vector<Point2f> filmGrid(const Scene& scene, int grid, PCG32* jitter = nullptr);

/// Probes through grid x grid film positions (cell centres of the crop
/// window, aperture centre); unbounded pieces end as camera segments do
/// (unboundedSegmentLength, with `horizon`; camera segments add no OPL
/// without `observerTime`). Deterministic.
constexpr int ProbeGrid = 8;
std::vector<ProbeSegment> probeSegments(const Scene& scene, double horizon, bool observerTime, int grid = ProbeGrid);

/// Probes through the border of the film's crop window, EdgeProbes + 1 per
/// side: the view's edge, which the light bound measures its gap to
/// (light_leak.h). Deterministic.
std::vector<ProbeSegment> edgeProbeSegments(const Scene& scene, double horizon, bool observerTime);

/// Spacing of 1/256 of the film's side: on a 30-degree view 4.5 units away,
/// 0.009 between rays, below the gaps that matter (a few radii of 0.01-0.1).
constexpr int EdgeProbes = 256;

}  // namespace femto::beams
