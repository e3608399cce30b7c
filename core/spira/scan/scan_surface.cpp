#include "spira/scan/scan_surface.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "spira/base/error.h"
#include "spira/base/number_text.h"

namespace spira {

double heightFieldCell(const PointCloud& scan)
{
  const BoundingBox box = boundsOf(scan);
  if (scan.empty() || box.empty()) return 1.0;
  const double area = std::max(1e-9, box.size().x() * box.size().y());
  return std::max(0.5, 2.0 * std::sqrt(area / double(scan.size())));
}

TriangleMesh heightFieldFromScan(const PointCloud& scan, double cell, double maxSpread)
{
  if (!(cell > 0.0))
    throw InputError("a height-field cell of " + significantText(cell, 4) + " mm", "give it above 0");
  const BoundingBox box = boundsOf(scan);
  if (scan.size() < 3 || box.empty())
    throw InputError("a substrate scan of " + std::to_string(scan.size()) + " point(s)",
                     "scan the substrate's whole top surface");
  const long nx = long(std::floor(box.size().x() / cell)) + 1,
             ny = long(std::floor(box.size().y() / cell)) + 1;
  if (double(nx) * double(ny) > 2e7)
    throw InputError("the substrate scan spans " + significantText(box.size().x(), 4) + " x " +
                         significantText(box.size().y(), 4) + " mm, too many " + significantText(cell, 3) +
                         " mm cells",
                     "scan the plate only, or thin the scan");
  std::vector<std::vector<double>> heights(size_t(nx * ny));
  for (const Vec3& p : scan.points) {
    const long i = std::min(nx - 1, long((p.x() - box.min.x()) / cell));
    const long j = std::min(ny - 1, long((p.y() - box.min.y()) / cell));
    heights[size_t(j * nx + i)].push_back(p.z());
  }
  std::vector<double> z(heights.size(), NAN);
  for (size_t c = 0; c < heights.size(); ++c) {
    std::vector<double>& h = heights[c];
    if (h.empty()) continue;
    std::sort(h.begin(), h.end());
    // The 5th and 95th percentiles: a stray point does not make a plate a wall.
    const double spread = h[h.size() - 1 - h.size() / 20] - h[h.size() / 20];
    if (spread > maxSpread) {
      const double x = box.min.x() + (double(c % size_t(nx)) + 0.5) * cell;
      const double y = box.min.y() + (double(c / size_t(nx)) + 0.5) * cell;
      throw InputError(
          "the substrate scan is not a plate seen from above: near (" + significantText(x, 4) + ", " +
              significantText(y, 4) + ") mm it holds points " + significantText(spread, 3) +
              " mm apart in height",
          "give a scan of the plate's top surface only, or the substrate as a mesh (--substrate FILE)");
    }
    z[c] = h[h.size() / 2];
  }
  // Holes surrounded on both sides (a shadowed cell, a dropped line) take their neighbours' mean.
  for (int pass = 0; pass < 3; ++pass) {
    std::vector<double> filled = z;
    for (long j = 0; j < ny; ++j)
      for (long i = 0; i < nx; ++i) {
        if (!std::isnan(z[size_t(j * nx + i)])) continue;
        double sum = 0.0;
        int n = 0;
        const auto at = [&](long a, long b) {
          return a >= 0 && b >= 0 && a < nx && b < ny ? z[size_t(b * nx + a)] : double(NAN);
        };
        const bool acrossX = !std::isnan(at(i - 1, j)) && !std::isnan(at(i + 1, j));
        const bool acrossY = !std::isnan(at(i, j - 1)) && !std::isnan(at(i, j + 1));
        if (!acrossX && !acrossY) continue;
        for (const auto& [a, b] : {std::pair{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}})
          if (!std::isnan(at(a, b))) sum += at(a, b), ++n;
        filled[size_t(j * nx + i)] = sum / n;
      }
    z = std::move(filled);
  }
  TriangleMesh mesh;
  std::vector<int> index(z.size(), -1);
  for (long j = 0; j < ny; ++j)
    for (long i = 0; i < nx; ++i) {
      const size_t c = size_t(j * nx + i);
      if (std::isnan(z[c])) continue;
      index[c] = int(mesh.vertices.size());
      mesh.vertices.emplace_back(box.min.x() + (double(i) + 0.5) * cell,
                                 box.min.y() + (double(j) + 0.5) * cell, z[c]);
    }
  for (long j = 0; j + 1 < ny; ++j)
    for (long i = 0; i + 1 < nx; ++i) {
      const int a = index[size_t(j * nx + i)], b = index[size_t(j * nx + i + 1)];
      const int c = index[size_t((j + 1) * nx + i + 1)], d = index[size_t((j + 1) * nx + i)];
      // Counter-clockwise seen from above: the normals face up, out of the plate.
      if (a >= 0 && b >= 0 && c >= 0) mesh.faces.push_back({a, b, c});
      if (a >= 0 && c >= 0 && d >= 0) mesh.faces.push_back({a, c, d});
    }
  if (mesh.faces.empty())
    throw InputError(
        "the substrate scan covers no two neighbouring " + significantText(cell, 3) + " mm cells",
        "give a denser scan of the plate");
  return mesh;
}

}  // namespace spira
