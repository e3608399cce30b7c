#include "spira/contour/meshed_tube.h"

#include <cmath>
#include <limits>
#include <string>

#include "spira/base/error.h"
#include "spira/contour/guided_tube.h"
#include "spira/mesh/ray_bvh.h"

namespace spira {
namespace {

// The mesh and its tree, shared by the surface's copies.
struct Hull {
  explicit Hull(const TriangleMesh& m) : mesh(m), tree(mesh) {}
  TriangleMesh mesh;
  RayBvh tree;
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
  tube.at = [unit, guide = std::move(guide), hull, reach](double t, double v) {
    const Vec3 centre = guide(t);
    const Vec3 across = unit.at(t, v) - centre;
    const RayHit hit = hull->tree.firstHit(centre, across, 0.0, reach);
    constexpr double kMissed = std::numeric_limits<double>::quiet_NaN();
    return hit.face < 0 ? Vec3(kMissed, kMissed, kMissed) : Vec3(centre + hit.distance * across);
  };
  for (int k = 0; k < 8; ++k) {
    const double v = 2.0 * 3.14159265358979323846 * k / 8;
    if (!tube.at(t0, v).allFinite())
      throw InputError("the guide curve's base at t = " + std::to_string(t0) + " sees no wall within " +
                           std::to_string(reach) + " mm across it",
                       "give a guide that runs inside the tube (its centre line)");
  }
  return tube;
}

}  // namespace spira
