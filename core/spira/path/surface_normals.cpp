#include "spira/path/surface_normals.h"

#include <string>

#include "spira/base/error.h"
#include "spira/path/arc_length_polyline.h"

namespace spira {

std::vector<std::vector<Vec3>> estimateNormals(const Generatrices& g)
{
  const size_t n = g.lines.size();
  if (n < 3)
    throw InputError("surface normals cannot be estimated from fewer than 3 generatrices",
                     "supply normals with the generatrices or decompose the part into more generatrices");
  // Only positions are read from the neighbours; their normals are never used.
  std::vector<std::vector<Vec3>> unusedNormals(n);
  std::vector<ArcLengthPolyline> arcs;
  arcs.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    unusedNormals[i].assign(g.lines[i].size(), Vec3::UnitZ());
    arcs.emplace_back(g.lines[i], unusedNormals[i]);
  }

  std::vector<std::vector<Vec3>> normals(n);
  for (size_t i = 0; i < n; ++i) {
    const Polyline& line = g.lines[i];
    const size_t m = line.size();
    const ArcLengthPolyline& prev = arcs[(i + n - 1) % n];
    const ArcLengthPolyline& next = arcs[(i + 1) % n];
    std::vector<Vec3>& out = normals[i];
    out.assign(m, Vec3::Zero());
    std::vector<bool> valid(m, false);
    double s = 0.0;
    for (size_t k = 0; k < m; ++k) {
      if (k > 0) s += (line[k] - line[k - 1]).norm();
      const double f = arcs[i].length() > 0.0 ? s / arcs[i].length() : 0.0;
      const Vec3 across = next.at(f * next.length()).position - prev.at(f * prev.length()).position;
      const Vec3 along = line[std::min(k + 1, m - 1)] - line[k > 0 ? k - 1 : 0];
      const Vec3 c = across.cross(along);
      const double scale = across.norm() * along.norm();
      if (scale > 0.0 && c.norm() > 1e-6 * scale) {
        out[k] = c.normalized();
        valid[k] = true;
      }
    }
    // Copy the nearest regular normal into degenerate points (where the neighbours meet).
    size_t firstValid = m;
    for (size_t k = 0; k < m && firstValid == m; ++k)
      if (valid[k]) firstValid = k;
    if (firstValid == m)
      throw InputError("no surface normal can be estimated along generatrix " + std::to_string(i) +
                           ": its neighbours coincide with it",
                       "supply normals with the generatrices or check the decomposition");
    for (size_t k = 0; k < firstValid; ++k) out[k] = out[firstValid];
    for (size_t k = firstValid + 1; k < m; ++k)
      if (!valid[k]) out[k] = out[k - 1];
  }
  return normals;
}

}  // namespace spira
