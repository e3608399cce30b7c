#include "spira/path/facet_normals.h"

#include <limits>
#include <string>

#include "spira/base/error.h"
#include "spira/base/segment_distance.h"

namespace spira {

Vec3 nearestOnLoop(const Vec3& p, const Polyline& loop)
{
  Vec3 best = loop.front();
  double bestDistance = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < loop.size(); ++i) {
    const Vec3 q = closestPointOnSegment(p, loop[i], loop[(i + 1) % loop.size()]);
    const double d = (q - p).squaredNorm();
    if (d < bestDistance) bestDistance = d, best = q;
  }
  return best;
}

std::vector<std::vector<Vec3>> facetNormals(const std::vector<Polyline>& layers)
{
  if (layers.size() < 2)
    throw InputError("the numerical frame needs two or more layers, found " + std::to_string(layers.size()),
                     "give the path's layers in build order");
  for (size_t k = 0; k < layers.size(); ++k)
    if (layers[k].size() < 3)
      throw InputError("layer " + std::to_string(k) + " has " + std::to_string(layers[k].size()) +
                           " points; a closed layer needs 3 or more",
                       "give each layer as a closed loop of points");
  std::vector<std::vector<Vec3>> normals(layers.size());
  for (size_t k = 0; k < layers.size(); ++k) {
    const Polyline& layer = layers[k];
    const size_t n = layer.size();
    normals[k].resize(n);
    for (size_t v = 0; v < n; ++v) {
      const Vec3& ahead = layer[(v + 1) % n];
      const Vec3& behind = layer[(v + n - 1) % n];
      const Vec3 along = ahead - behind;
      const Vec3 middle = 0.5 * (ahead + behind);
      // Each facet holds `along` and a direction up the wall (from its third point to the middle of
      // the first two, or back); its normal, along x up, is oriented so that b = n x t points up.
      Vec3 sum = Vec3::Zero();
      if (k > 0) sum += along.cross(middle - nearestOnLoop(layer[v], layers[k - 1])).normalized();
      if (k + 1 < layers.size())
        sum += along.cross(nearestOnLoop(layer[v], layers[k + 1]) - middle).normalized();
      normals[k][v] = sum.normalized();
    }
  }
  return normals;
}

}  // namespace spira
