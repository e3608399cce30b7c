#include "spira/scan/scan_simulator.h"

#include <random>

#include "spira/scan/scan_alignment.h"

namespace spira {

PointCloud simulateSurfaceScan(const TriangleMesh& mesh, double spacing, const ScanErrors& errors,
                               std::uint64_t seed)
{
  const PointCloud surface = sampleSurface(mesh, spacing);
  std::mt19937_64 random(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  PointCloud out;
  out.points.reserve(surface.size());
  for (size_t i = 0; i < surface.size(); ++i) {
    Vec3 p = errors.scaleCentre + errors.scale * (surface.points[i] - errors.scaleCentre);
    if (errors.noiseMm > 0.0) p += errors.noiseMm * noise(random) * surface.normals[i];
    out.points.push_back(errors.misalignment * p);
  }
  return out;
}

}  // namespace spira
