#pragma once

#include <cstdint>

#include "spira/mesh/triangle_mesh.h"
#include "spira/scan/point_cloud.h"

namespace spira {

// What a simulated scanner gets wrong, applied in this order: the surface scaled by `scale` about
// `scaleCentre` (a part grown larger or smaller), gaussian noise of `noiseMm` (one standard
// deviation) along the surface normal, then the whole scan moved by `misalignment` (the scanner's
// frame off the part's).
struct ScanErrors {
  double scale = 1.0;
  Vec3 scaleCentre = Vec3::Zero();
  double noiseMm = 0.0;
  Transform misalignment = Transform::Identity();
};

// A laser-line scan of `mesh` made in code, for tests and demos: points about `spacing` mm apart on
// its surface (sampleSurface), without normals, as a scanner delivers them. Repeatable for a seed.
PointCloud simulateSurfaceScan(const TriangleMesh& mesh, double spacing, const ScanErrors& errors,
                               std::uint64_t seed = 1);

}  // namespace spira
