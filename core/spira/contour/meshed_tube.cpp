#include "spira/contour/meshed_tube.h"

#include <cmath>
#include <limits>
#include <string>

#include "spira/base/error.h"
#include "spira/contour/guided_tube.h"
#include "spira/contour/surface_point.h"
#include "spira/mesh/corner_normals.h"
#include "spira/mesh/ray_bvh.h"

namespace spira {
namespace {

// The mesh and its tree, shared by the surface's copies.
struct Hull {
  explicit Hull(const TriangleMesh& m) : mesh(m), tree(mesh), corners(cornerNormals(mesh)) {}
  TriangleMesh mesh;
  RayBvh tree;
  std::vector<Vec3> corners;
};

}  // namespace

TubeSurface meshedTube(const TriangleMesh& mesh, std::function<Vec3(double)> guide, double t0, double t1,
                       double reach, int samples)
{
  if (mesh.faces.empty()) throw InputError("the tube's mesh has no faces", "import the part first");
  // The unit-radius tube on the guide gives, per (t, v), the guide point and the direction across it.
  const TubeSurface unit = guidedTube(
      guide, [](double) { return 1.0; }, t0, t1, samples);
  auto hull = std::make_shared<const Hull>(mesh);
  TubeSurface tube;
  tube.t0 = t0;
  tube.tEnd = t1;
  tube.at = [unit, guide, hull, reach](double t, double v) {
    const Vec3 centre = guide(t);
    const Vec3 across = unit.at(t, v) - centre;
    const RayHit hit = hull->tree.firstHit(centre, across, 0.0, reach);
    constexpr double kMissed = std::numeric_limits<double>::quiet_NaN();
    return hit.face < 0 ? Vec3(kMissed, kMissed, kMissed) : Vec3(centre + hit.distance * across);
  };
  tube.normal = [unit, guide, hull, reach](double t, double v) {
    const Vec3 centre = guide(t);
    const Vec3 across = unit.at(t, v) - centre;
    const RayHit hit = hull->tree.firstHit(centre, across, 0.0, reach);
    if (hit.face < 0) return Vec3(across.normalized());
    const Vec3 p = centre + hit.distance * across;
    Vec3 n = surfaceNormalAt(hull->mesh, hull->corners, closestPointOnFace(hull->mesh, hit.face, p));
    return Vec3(n.dot(across) < 0.0 ? -n : n);
  };
  bool seen = false;
  for (int k = 0; k < 16 * 8 && !seen; ++k)
    seen = tube.at(t0 + (t1 - t0) * (k / 8) / 15.0, layerAngle(k % 8, 8)).allFinite();
  if (!seen)
    throw InputError("no ray across the guide curve meets the tube within " + std::to_string(reach) + " mm",
                     "give a guide that runs inside the tube (its centre line)");
  return tube;
}

namespace {

// Per point, the t in [from, to] where the ray first meets the mesh, scanning from `from` towards `to`
// (either direction) and bisecting to `tolerance`.
std::vector<double> edgeLayer(const TubeSurface& tube, int points, double from, double to, double tolerance)
{
  std::vector<double> t;
  const double step = (to - from) / 256;
  const double span = std::abs(to - from);
  for (int i = 0; i < points; ++i) {
    const double v = layerAngle(i, points);
    double outside = from, inside = from;
    while (std::abs(inside - from) <= span && !tube.at(inside, v).allFinite())
      outside = inside, inside += step;
    if (std::abs(inside - from) > span)
      throw InputError("no ray across the guide meets the tube at v = " + std::to_string(v) + " rad",
                       "check that the guide runs inside the tube");
    if (inside != from)
      while (std::abs(inside - outside) > tolerance) {
        const double mid = 0.5 * (outside + inside);
        (tube.at(mid, v).allFinite() ? inside : outside) = mid;
      }
    t.push_back(inside);
  }
  return t;
}

}  // namespace

std::vector<double> baseLayer(const TubeSurface& tube, int points, double tFrom, double tTo, double tolerance)
{
  return edgeLayer(tube, points, tFrom, tTo, tolerance);
}

std::vector<double> topLayer(const TubeSurface& tube, int points, double tFrom, double tTo, double tolerance)
{
  return edgeLayer(tube, points, tTo, tFrom, tolerance);
}

}  // namespace spira
