#include "length_spread.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <sstream>

#include "spira/base/error.h"
#include "spira/base/number_text.h"

namespace spira::geodesic {

namespace {

double distanceToLoop(const TriangleMesh& mesh, const BoundaryLoop& loop, const Vec3& q)
{
  const auto& X = mesh.vertices;
  const auto& v = loop.vertices;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < v.size(); ++i) {
    const Vec3& a = X[size_t(v[i])];
    const Vec3 d = X[size_t(v[(i + 1) % v.size()])] - a;
    const double dd = d.squaredNorm();
    const double t = dd > 0.0 ? std::clamp((q - a).dot(d) / dd, 0.0, 1.0) : 0.0;
    best = std::min(best, (a + t * d - q).norm());
  }
  return best;
}

// Dijkstra along mesh edges from `sources` (each with its starting distance).
std::vector<double> edgeDistances(const GeodesicMesh& gm, const std::vector<std::pair<int, double>>& sources)
{
  const TriangleMesh& mesh = gm.mesh();
  std::vector<double> dist(mesh.vertexCount(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (const auto& [v, d] : sources)
    if (d < dist[size_t(v)]) {
      dist[size_t(v)] = d;
      queue.emplace(d, v);
    }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[size_t(v)]) continue;
    for (const int* c = gm.cornersBegin(v); c != gm.cornersEnd(v); ++c) {
      const Face& f = mesh.faces[size_t(*c / 3)];
      for (int u : f) {
        const double du = d + (mesh.vertices[size_t(u)] - mesh.vertices[size_t(v)]).norm();
        if (du < dist[size_t(u)]) {
          dist[size_t(u)] = du;
          queue.emplace(du, u);
        }
      }
    }
  }
  return dist;
}

}  // namespace

std::vector<LengthBounds> boundGeneratrixLengths(const GeodesicMesh& gm, const std::vector<BasePoint>& bases,
                                                 const GeodesicTarget& target)
{
  const TriangleMesh& mesh = gm.mesh();
  std::vector<std::pair<int, double>> sources;
  if (target.open()) {
    for (int v : target.upper->vertices) sources.emplace_back(v, 0.0);
  } else {
    // The closure point is reached straight across its face from each of the face's corners.
    const Face& f = mesh.faces[size_t(target.closure.face)];
    for (int v : f) sources.emplace_back(v, (mesh.vertices[size_t(v)] - target.closure.position).norm());
  }
  const std::vector<double> along = edgeDistances(gm, sources);
  std::vector<LengthBounds> out(bases.size());
  for (size_t i = 0; i < bases.size(); ++i) {
    const SurfacePoint& p = bases[i].point;
    out[i].lower = target.open() ? distanceToLoop(mesh, *target.upper, p.position)
                                 : (target.closure.position - p.position).norm();
    out[i].upper = std::numeric_limits<double>::infinity();
    for (int v : mesh.faces[size_t(p.face)])
      out[i].upper =
          std::min(out[i].upper, (mesh.vertices[size_t(v)] - p.position).norm() + along[size_t(v)]);
  }
  return out;
}

void requireLengthsFitWindow(const std::vector<LengthBounds>& lengths, const std::vector<BasePoint>& bases,
                             const LayerWindow& window, bool open)
{
  if (!window.known() || lengths.empty()) return;
  size_t longest = 0, shortest = 0;
  for (size_t i = 1; i < lengths.size(); ++i) {
    if (lengths[i].lower > lengths[longest].lower) longest = i;
    if (lengths[i].upper < lengths[shortest].upper) shortest = i;
  }
  const double ratio = lengths[longest].lower / lengths[shortest].upper;
  if (!(ratio > window.lengthRatio())) return;
  const bool exact = lengths[longest].lower == lengths[longest].upper;
  const std::string target = open ? "upper edge" : "closure point";
  std::ostringstream what;
  what << "the geodesic generatrices cannot be laid by one spiral in the window " << fixedText(window.hMin, 2)
       << " .. " << fixedText(window.hMax, 2) << " mm: the shortest path on the surface to the " << target
       << " is " << (exact ? "" : "at least ") << fixedText(lengths[longest].lower, 1)
       << " mm from the base point at " << pointText(bases[longest].point.position, 1) << " but "
       << (exact ? "" : "at most ") << fixedText(lengths[shortest].upper, 1) << " mm from "
       << pointText(bases[shortest].point.position, 1)
       << ", so layers laid at equal fractions of them differ in thickness by a factor of "
       << (exact ? "" : "at least ") << fixedText(ratio, 2)
       << ", more than h_max / h_min = " << fixedText(window.lengthRatio(), 2)
       << " (thesis Eq. 3.6; the wall bends or leans so that shortest paths "
       << "take very different routes)";
  throw InputError(
      what.str(),
      "use --strategy isovalue: its layers follow the part's own field instead of shortest paths");
}

}  // namespace spira::geodesic
