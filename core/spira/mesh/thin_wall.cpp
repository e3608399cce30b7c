#include "spira/mesh/thin_wall.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "spira/mesh/ray_bvh.h"
#include "spira/mesh/wall_skin.h"

namespace spira {
namespace {

// Skins face each other when their outward normals are within 60 degrees of opposite; a ray that
// leaves through a side wall instead (a corner) does not measure the wall.
constexpr double kFacingCos = -0.5;
// One pass of neighbour averaging blends the per-vertex thickness so a step in the wall does not
// tear the mid-surface; more would spread a thin groove over the long faces of a coarse export.
constexpr int kSmoothingPasses = 1;
// Rings a ledge's thickness is carried over from the wall faces round it; wider ledges keep
// their skin where it is.
constexpr int kMaxFillPasses = 16;

struct FaceRay {
  double thickness = std::numeric_limits<double>::infinity();
  int hitFace = -1;
  bool facing = false;  // the ray left through a skin facing this face
};

std::vector<FaceRay> castInwardRays(const TriangleMesh& mesh, double diagonal)
{
  const RayBvh bvh(mesh);
  std::vector<FaceRay> rays(mesh.faceCount());
  const double minDistance = 1e-9 * diagonal;
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, mesh.faceCount(), 256), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t f = r.begin(); f != r.end(); ++f) {
          const Vec3 n = mesh.faceNormalScaled(f);
          const double len = n.norm();
          if (!(len > 0.0) || !std::isfinite(len)) continue;
          const Vec3 inward = -n / len;
          const Face& t = mesh.faces[f];
          const Vec3 c = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
          const RayHit hit = bvh.firstHit(c, inward, minDistance, 2.0 * diagonal, static_cast<int>(f));
          if (hit.face < 0) continue;
          rays[f].thickness = hit.distance;
          rays[f].hitFace = hit.face;
          rays[f].facing = -inward.dot(mesh.faceNormal(static_cast<size_t>(hit.face))) < kFacingCos;
        }
      });
  return rays;
}

double signedVolume(const TriangleMesh& m)
{
  double v = 0.0;
  for (const Face& f : m.faces) v += m.vertices[f[0]].dot(m.vertices[f[1]].cross(m.vertices[f[2]]));
  return v / 6.0;
}

// The value at area fraction p of (value, area) pairs sorted by value.
double areaPercentile(const std::vector<std::pair<double, double>>& sorted, double total, double p)
{
  double sum = 0.0;
  for (const auto& [value, area] : sorted) {
    sum += area;
    if (sum >= p * total) return value;
  }
  return sorted.empty() ? 0.0 : sorted.back().first;
}

WallThickness thicknessOf(const TriangleMesh& mesh, const std::vector<FaceRay>& rays,
                          const std::vector<std::uint8_t>& use)
{
  std::vector<std::pair<double, double>> samples;
  double total = 0.0;
  for (size_t f = 0; f < rays.size(); ++f) {
    if (!use[f]) continue;
    const double a = mesh.faceArea(f);
    samples.emplace_back(rays[f].thickness, a);
    total += a;
  }
  std::sort(samples.begin(), samples.end());
  WallThickness w;
  w.median = areaPercentile(samples, total, 0.5);
  w.thinnest = areaPercentile(samples, total, 0.02);
  w.thickest = areaPercentile(samples, total, 0.98);
  return w;
}

struct NeighbourSums {
  std::vector<double> sum, count;
};

// Per vertex, the sum and count of the known values at the corners of its skin faces (itself too).
NeighbourSums neighbourSums(const TriangleMesh& mesh, const std::vector<std::uint8_t>& skin,
                            const std::vector<double>& value, const std::vector<std::uint8_t>& known)
{
  NeighbourSums n{std::vector<double>(mesh.vertexCount(), 0.0), std::vector<double>(mesh.vertexCount(), 0.0)};
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    if (!skin[f]) continue;
    for (int w : mesh.faces[f]) {
      if (!known[static_cast<size_t>(w)]) continue;
      for (int v : mesh.faces[f]) {
        n.sum[static_cast<size_t>(v)] += value[static_cast<size_t>(w)];
        n.count[static_cast<size_t>(v)] += 1.0;
      }
    }
  }
  return n;
}

// Per skin vertex, the wall's thickness: the thickness of its wall faces (area-weighted), carried onto
// vertices of faces without one (a ledge, a grazed face) from their neighbours, then smoothed.
std::vector<double> vertexThickness(const TriangleMesh& mesh, const std::vector<FaceRay>& rays,
                                    const std::vector<std::uint8_t>& wall,
                                    const std::vector<std::uint8_t>& skin)
{
  const size_t nv = mesh.vertexCount();
  std::vector<double> thick(nv, 0.0), weight(nv, 0.0);
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    if (!skin[f] || !wall[f]) continue;
    const double a = mesh.faceArea(f);
    for (int v : mesh.faces[f]) {
      thick[static_cast<size_t>(v)] += a * rays[f].thickness;
      weight[static_cast<size_t>(v)] += a;
    }
  }
  std::vector<std::uint8_t> known(nv, 0);
  for (size_t v = 0; v < nv; ++v)
    if (weight[v] > 0.0) {
      thick[v] /= weight[v];
      known[v] = 1;
    }
  // Vertices without a wall face take their known neighbours' mean, ring by ring, then every
  // vertex is smoothed the same way.
  for (int pass = 0; pass < kMaxFillPasses && std::count(known.begin(), known.end(), 0) > 0; ++pass) {
    const NeighbourSums n = neighbourSums(mesh, skin, thick, known);
    for (size_t v = 0; v < nv; ++v)
      if (!known[v] && n.count[v] > 0.0) thick[v] = n.sum[v] / n.count[v];
    for (size_t v = 0; v < nv; ++v) known[v] = known[v] || n.count[v] > 0.0;
  }
  for (int pass = 0; pass < kSmoothingPasses; ++pass) {
    const NeighbourSums n = neighbourSums(mesh, skin, thick, known);
    for (size_t v = 0; v < nv; ++v)
      if (n.count[v] > 0.0) thick[v] = n.sum[v] / n.count[v];
  }
  return thick;
}

// The skin's vertices moved inward by half the local thickness, re-indexed into a mesh of their own.
TriangleMesh offsetSkin(const TriangleMesh& mesh, const std::vector<double>& thick,
                        const std::vector<std::uint8_t>& skin)
{
  const size_t nv = mesh.vertexCount();
  std::vector<Vec3> normal(nv, Vec3::Zero());
  for (size_t f = 0; f < mesh.faceCount(); ++f)
    if (skin[f])
      for (int v : mesh.faces[f]) normal[static_cast<size_t>(v)] += mesh.faceNormalScaled(f);
  std::vector<int> index(nv, -1);
  TriangleMesh mid;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    if (!skin[f]) continue;
    Face out;
    for (int k = 0; k < 3; ++k) {
      const size_t v = static_cast<size_t>(mesh.faces[f][static_cast<size_t>(k)]);
      if (index[v] < 0) {
        index[v] = static_cast<int>(mid.vertices.size());
        mid.vertices.push_back(mesh.vertices[v] - 0.5 * thick[v] * normal[v].normalized());
      }
      out[static_cast<size_t>(k)] = index[v];
    }
    mid.faces.push_back(out);
  }
  return mid;
}

std::string describe(const ThinWallAnalysis& a)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << "walls " << a.thickness.median << " mm thick (median; "
    << a.thickness.thinnest << " .. " << a.thickness.thickest << " mm) over " << std::setprecision(0)
    << 100.0 * a.wallAreaFraction << " % of its surface, " << std::setprecision(1)
    << 100.0 * a.thickness.median / a.diagonal << " % of its size (bounding-box diagonal "
    << std::setprecision(1) << a.diagonal << " mm)";
  return s.str();
}

}  // namespace

ThinWallAnalysis analyseClosedSolid(const TriangleMesh& input)
{
  // An export with every face turned inside out is still one solid: measured the right way out.
  TriangleMesh flipped;
  if (signedVolume(input) < 0.0) {
    flipped = input;
    for (Face& f : flipped.faces) std::swap(f[1], f[2]);
  }
  const TriangleMesh& mesh = flipped.empty() ? input : flipped;
  ThinWallAnalysis a;
  a.diagonal = mesh.bounds().diagonal();
  if (mesh.empty() || !(a.diagonal > 0.0)) {
    a.reason = "the mesh has no extent";
    return a;
  }
  const std::vector<FaceRay> rays = castInwardRays(mesh, a.diagonal);
  std::vector<std::uint8_t> wall(mesh.faceCount(), 0);
  for (size_t f = 0; f < rays.size(); ++f) wall[f] = rays[f].facing;
  const double facingMedian = thicknessOf(mesh, rays, wall).median;
  double wallArea = 0.0, total = 0.0;
  for (size_t f = 0; f < rays.size(); ++f) {
    wall[f] = wall[f] && rays[f].thickness <= kRimFactor * facingMedian;
    const double area = mesh.faceArea(f);
    total += area;
    if (wall[f]) wallArea += area;
  }
  a.wallAreaFraction = total > 0.0 ? wallArea / total : 0.0;
  if (wallArea <= 0.0) {
    a.reason = "a solid body: no two faces of it face each other across the material";
    return a;
  }
  a.thickness = thicknessOf(mesh, rays, wall);
  const bool thin =
      a.thickness.median <= kThinWallMaxRelativeThickness * a.diagonal && a.wallAreaFraction >= 0.5;
  a.reason = (thin ? "a thin-walled solid: " : "a solid body, not a thin wall: ") + describe(a) +
             (thin ? "" : "; a thin wall is at most 10 % of the size thick over at least half its surface");
  if (!thin) return a;
  a.kind = SolidKind::ThinWalled;
  std::vector<int> hitFace(rays.size());
  for (size_t f = 0; f < rays.size(); ++f) hitFace[f] = rays[f].hitFace;
  const std::vector<std::uint8_t> skin = outerSkin(mesh, wall, hitFace);
  a.skinFaces = static_cast<size_t>(std::count(skin.begin(), skin.end(), 1));
  a.midSurface = offsetSkin(mesh, vertexThickness(mesh, rays, wall, skin), skin);
  return a;
}

}  // namespace spira
