// Iso-contour extraction and iso-value decomposition on ~100,000-triangle analytic parts.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "best_of.h"
#include "builtin_plugins.h"
#include "spira/base/units.h"
#include "spira/contour/contour_loop.h"
#include "spira/contour/isovalue_decomposition.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/plugin/plugin_registry.h"

namespace {

using namespace spira;

void run(const char* name, const TriangleMesh& mesh, const std::vector<double>& field, bool open,
         double spacing, double expectedLength)
{
  const MeshReport report = validateMesh(mesh);
  const BoundaryLoop* upper = open ? &report.boundaryLoops[1] : nullptr;
  IsoDecompositionOptions opt;
  opt.pointsPerContour = 360;
  opt.levelSpacing = spacing;
  NullProgress progress;

  // The levels the decomposition uses, for the extraction-only timing.
  IsoDecomposition d =
      decomposeByIsoValues(mesh, field, report.boundaryLoops[0], upper, std::nullopt, opt, progress);
  std::vector<double> levels;
  for (size_t c = 1; c + (open ? 1 : 0) < d.contours.size(); ++c) levels.push_back(d.contours[c].level);

  size_t crossings = 0;
  const double tExtract = bestOf(5, [&] {
    const auto l = extractIsoContours(mesh, field, levels);
    crossings = 0;
    for (const auto& x : l)
      for (const auto& c : x.contours) crossings += c.points.size();
  });
  const double tDecompose = bestOf(5, [&] {
    d = decomposeByIsoValues(mesh, field, report.boundaryLoops[0], upper, std::nullopt, opt, progress);
  });
  double lo = 1e300, hi = 0;
  for (const auto& l : d.generatrices.lines) {
    lo = std::min(lo, polylineLength(l, false));
    hi = std::max(hi, polylineLength(l, false));
  }
  std::printf(
      "%-10s %7zu faces  %3zu levels  %6zu contour points  extract %6.1f ms  decompose(360 pts) %6.1f ms\n",
      name, mesh.faceCount(), levels.size(), crossings, 1e3 * tExtract, 1e3 * tDecompose);
  std::printf("%-10s generatrix length %.4f .. %.4f mm, expected %.4f mm (max error %.3f %%)\n", "", lo, hi,
              expectedLength,
              100 * std::max(std::abs(lo - expectedLength), std::abs(hi - expectedLength)) / expectedLength);
}

// The plugin end to end, computing the thesis's field itself (harmonic or heat-method distance).
void runPlugin(const char* name, const TriangleMesh& mesh, double expectedLength)
{
  const MeshReport report = validateMesh(mesh);
  const bool open = report.partClass == PartClass::Open;
  DecomposeInput in{mesh, report.partClass, report.boundaryLoops[0],
                    open ? std::optional<BoundaryLoop>(report.boundaryLoops[1]) : std::nullopt, std::nullopt};
  const DecomposerPlugin& plugin = builtinRegistry().decomposer("decomposer.isovalue");
  NullProgress progress;
  DecomposeResult res;
  const double t = bestOf(3, [&] { res = plugin.decompose(in, ParamSet{}, progress); });
  double lo = 1e300, hi = 0;
  for (const auto& l : res.generatrices.lines) {
    lo = std::min(lo, polylineLength(l, false));
    hi = std::max(hi, polylineLength(l, false));
  }
  std::printf(
      "%-10s plugin with its own field: %6.1f ms; generatrix length %.4f .. %.4f mm, expected %.4f mm "
      "(max error %.3f %%)\n",
      name, 1e3 * t, lo, hi, expectedLength,
      100 * std::max(std::abs(lo - expectedLength), std::abs(hi - expectedLength)) / expectedLength);
}

}  // namespace

int main()
{
  {
    const double R = 50, H = 100;
    const TriangleMesh m = makeOpenCylinder(R, H, 500, 100);
    std::vector<double> f;
    for (const auto& v : m.vertices) f.push_back(v.z() / H);
    run("cylinder", m, f, true, 1.0, H);
    runPlugin("cylinder", m, H);
  }
  {
    const double R = 50;
    const TriangleMesh m = makeHemisphere(R, 500, 100);
    std::vector<double> f;
    for (const auto& v : m.vertices) f.push_back(R * std::atan2(v.z(), std::hypot(v.x(), v.y())));
    run("hemisphere", m, f, false, 0.5 * kPi * R / 100, 0.5 * kPi * R);
    runPlugin("hemisphere", m, 0.5 * kPi * R);
  }
  return 0;
}
