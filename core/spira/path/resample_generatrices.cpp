#include "spira/path/resample_generatrices.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "spira/base/error.h"
#include "spira/path/arc_length_polyline.h"

namespace spira {

Generatrices resampleGeneratrices(const Generatrices& g, int count)
{
  if (count < 3)
    throw InputError("a revolution needs at least 3 points, " + std::to_string(count) + " were asked for",
                     "set the points per revolution to 3 or more, or 0 to keep one per generatrix");
  const size_t n = g.lines.size();
  std::vector<ArcLengthPolyline> arcs;
  arcs.reserve(n);
  for (size_t i = 0; i < n; ++i) arcs.emplace_back(g.lines[i], g.normals[i]);

  Generatrices out;
  out.hasClosurePoint = g.hasClosurePoint;
  out.closurePoint = g.closurePoint;
  out.lines.resize(count);
  out.normals.resize(count);
  for (int j = 0; j < count; ++j) {
    const double tau = static_cast<double>(j) * n / count;
    const size_t a = std::min(static_cast<size_t>(std::floor(tau)), n - 1);
    const double w = tau - a;
    if (w < 1e-12) {
      out.lines[j] = g.lines[a];
      out.normals[j] = g.normals[a];
      continue;
    }
    const size_t b = (a + 1) % n;
    const size_t m = std::max(g.lines[a].size(), g.lines[b].size());
    out.lines[j].resize(m);
    out.normals[j].resize(m);
    for (size_t k = 0; k < m; ++k) {
      const double f = static_cast<double>(k) / (m - 1);
      const auto sa = arcs[a].at(f * arcs[a].length());
      const auto sb = arcs[b].at(f * arcs[b].length());
      out.lines[j][k] = (1.0 - w) * sa.position + w * sb.position;
      const Vec3 nb = (1.0 - w) * sa.normal + w * sb.normal;
      out.normals[j][k] = nb.norm() > 1e-9 ? Vec3(nb.normalized()) : (w < 0.5 ? sa.normal : sb.normal);
    }
  }
  return out;
}

}  // namespace spira
