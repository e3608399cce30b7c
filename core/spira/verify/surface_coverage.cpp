#include "spira/verify/surface_coverage.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

namespace spira {
namespace {

constexpr size_t kMaxSamples = 2'000'000;
constexpr size_t kMaxGapSamples = 4'000;
constexpr int kMaxGapShells = 64;

struct Sample {
  Vec3 at;
  double weight;
};

std::vector<Sample> sampleSurface(const TriangleMesh& mesh, double spacing)
{
  auto splits = [&](size_t f) {
    const Face& t = mesh.faces[f];
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double edge = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    return std::max(1, static_cast<int>(std::ceil(edge / spacing)));
  };
  size_t total = 0;
  for (size_t f = 0; f < mesh.faces.size(); ++f) total += size_t(splits(f)) * size_t(splits(f));
  // A fine surface sampled this finely would cost more than the path it checks: coarsen evenly.
  while (total > kMaxSamples) {
    spacing *= 1.5;
    total = 0;
    for (size_t f = 0; f < mesh.faces.size(); ++f) total += size_t(splits(f)) * size_t(splits(f));
  }
  std::vector<Sample> samples;
  samples.reserve(total);
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const Face& t = mesh.faces[f];
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const int k = splits(f);
    const double w = mesh.faceArea(f) / (double(k) * k);
    // The k^2 sub-triangles of the regular split: k(k+1)/2 upright, k(k-1)/2 inverted.
    for (int i = 0; i < k; ++i)
      for (int j = 0; i + j < k; ++j) {
        const double u = (i + 1.0 / 3.0) / k, v = (j + 1.0 / 3.0) / k;
        samples.push_back({a + u * (b - a) + v * (c - a), w});
        if (i + j + 1 < k) {
          const double ui = (i + 2.0 / 3.0) / k, vi = (j + 2.0 / 3.0) / k;
          samples.push_back({a + ui * (b - a) + vi * (c - a), w});
        }
      }
  }
  return samples;
}

double nearestWithin(const Vec3& q, double radius, const std::vector<Vec3>& points, const SegmentGrid& grid,
                     std::vector<uint32_t>& scratch)
{
  scratch.clear();
  grid.collect(q.array() - radius, q.array() + radius, scratch);
  double best = std::numeric_limits<double>::infinity();
  for (uint32_t s : scratch) {
    const size_t j = grid.from(s);
    best = std::min(best, pointSegmentDistance(q, points[j], points[j + 1]));
  }
  return best;
}

// Whether a segment passes within the footprint's half width of q horizontally, no higher than
// its height above the substrate there.
bool underFootprint(const Vec3& q, const std::vector<Vec3>& points, const SegmentGrid& grid,
                    const SubstrateFootprint& f, std::vector<uint32_t>& scratch)
{
  const Vec3 lo(q.x() - f.halfWidth, q.y() - f.halfWidth, f.z - f.tolerance);
  const Vec3 hi(q.x() + f.halfWidth, q.y() + f.halfWidth, f.z + f.height + f.tolerance);
  scratch.clear();
  grid.collect(lo, hi, scratch);
  for (uint32_t s : scratch) {
    const size_t j = grid.from(s);
    const Vec3 &a = points[j], &c = points[j + 1];
    const Eigen::Vector2d d = (c - a).head<2>(), w = (q - a).head<2>();
    const double t = d.squaredNorm() > 0.0 ? std::clamp(w.dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    const Vec3 x = a + t * (c - a);
    if ((x - q).head<2>().norm() <= f.halfWidth && x.z() <= f.z + f.height + f.tolerance) return true;
  }
  return false;
}

}  // namespace

SurfaceCoverage measureCoverage(const TriangleMesh& surface, const std::vector<Vec3>& points,
                                const SegmentGrid& grid, double radius, double spacing,
                                const SubstrateFootprint& footprint, Progress& progress)
{
  SurfaceCoverage out;
  const std::vector<Sample> samples = sampleSurface(surface, spacing);
  // Exact below `radius`: every segment that near is in the searched box.
  std::vector<double> distance(samples.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, samples.size(), 4096), [&](const auto& range) {
    if (progress.cancelled()) return;
    std::vector<uint32_t> scratch;
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const Vec3& q = samples[i].at;
      distance[i] = nearestWithin(q, radius, points, grid, scratch);
      if (distance[i] > radius && footprint.halfWidth > 0.0 &&
          std::abs(q.z() - footprint.z) <= footprint.tolerance &&
          underFootprint(q, points, grid, footprint, scratch))
        distance[i] = radius;
    }
  });
  progress.checkCancel();
  std::vector<size_t> uncovered;
  auto note = [&](size_t i, double gap) {
    if (gap <= out.largestGap) return;
    out.largestGap = gap;
    out.largestGapAt = samples[i].at;
  };
  for (size_t i = 0; i < samples.size(); ++i) {
    out.area += samples[i].weight;
    if (distance[i] <= radius) {
      note(i, distance[i]);
    } else {
      out.uncoveredArea += samples[i].weight;
      uncovered.push_back(i);
    }
  }
  const size_t stride = std::max<size_t>(1, uncovered.size() / kMaxGapSamples);
  std::vector<uint32_t> scratch;
  for (size_t k = 0; k < uncovered.size(); k += stride) {
    const Vec3& q = samples[uncovered[k]].at;
    double gap = std::numeric_limits<double>::infinity();
    for (int shell = 1; shell <= kMaxGapShells; shell *= 2) {
      const double reach = std::max(radius, shell * grid.cell());
      gap = nearestWithin(q, reach, points, grid, scratch);
      if (gap <= reach) break;
    }
    note(uncovered[k], std::min(gap, kMaxGapShells * grid.cell()));
  }
  return out;
}

}  // namespace spira
