// The geodesic decomposer (decomposer.geodesic) on ~100,000-triangle parts made in code, 360
// generatrices: where the time goes, how the exact searches went, and the lengths against the
// closed-form geodesics. Target: under 5 s for the open part on a 2-core machine.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <thread>

#include "builtin_plugins.h"
#include "decomposer_geodesic/geodesic_decomposition.h"
#include "spira/base/units.h"
#include "spira/contour/contour_loop.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/plugin/plugin_registry.h"

namespace {

using namespace spira;

// `exact(line)`: the closed-form geodesic distance between the line's ends.
void run(const char* name, const TriangleMesh& mesh, bool open, const std::optional<Vec3>& closure,
         const std::function<double(const Polyline&)>& exact)
{
  const MeshReport report = validateMesh(mesh);
  geodesic::GeodesicOptions options;
  options.pointsPerRevolution = 360;
  NullProgress progress;
  geodesic::GeodesicDecomposition d;
  double best = 1e300;
  for (int run = 0; run < 3; ++run) {
    const auto t0 = std::chrono::steady_clock::now();
    d = geodesic::decomposeByGeodesics(mesh, report.boundaryLoops[0],
                                       open ? &report.boundaryLoops[1] : nullptr, closure, nullptr, options,
                                       progress);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  double worst = 0.0;
  for (size_t i = 0; i < d.generatrices.lines.size(); ++i) {
    if (d.fillIn[i]) continue;
    const double e = exact(d.generatrices.lines[i]);
    worst = std::max(worst, std::abs(polylineLength(d.generatrices.lines[i], false) - e) / e);
  }
  const geodesic::GeodesicStats& s = d.stats;
  std::printf("%-10s %7zu tri  %4zu lines  total %6.3f s  (guide %5.3f, paths %5.3f, coverage %5.3f)\n", name,
              mesh.faceCount(), d.generatrices.lines.size(), best, s.guideSeconds, s.pathSeconds,
              s.coverageSeconds);
  std::printf(
      "%-10s band %6.0f faces/search, widened %zu, whole mesh %zu, untraced %zu, fill-ins %zu, "
      "eps %.3f mm, worst length error vs closed form %.4f %%\n",
      "", s.meanBandFaces, s.widened, s.wholeMesh, s.untraced, s.fillIns, s.coverageError, 100.0 * worst);
}

}  // namespace

int main()
{
  std::printf("bench_geodesic: %u hardware threads\n", std::thread::hardware_concurrency());
  const double R = 50.0, H = 100.0;
  // 512 x 100 x 2 = 102,400 triangles.
  run("cylinder", makeOpenCylinder(R, H, 512, 100), true, std::nullopt, [&](const Polyline& l) {
    const double da = std::remainder(
        std::atan2(l.back().y(), l.back().x()) - std::atan2(l.front().y(), l.front().x()), 2.0 * kPi);
    return std::hypot(l.back().z() - l.front().z(), R * da);
  });
  const double r0 = 50.0, r1 = 30.0;
  const double slant = std::hypot(H, r0 - r1), sinHalf = (r0 - r1) / slant;
  run("cone", makeOpenCone(r0, r1, H, 512, 100), true, std::nullopt, [&](const Polyline& l) {
    const double rp = std::hypot(l.front().x(), l.front().y()) / sinHalf;
    const double rq = std::hypot(l.back().x(), l.back().y()) / sinHalf;
    const double da =
        std::remainder(std::atan2(l.back().y(), l.back().x()) - std::atan2(l.front().y(), l.front().x()),
                       2.0 * kPi) *
        sinHalf;
    return std::sqrt(rp * rp + rq * rq - 2.0 * rp * rq * std::cos(da));
  });
  // 448 x 112 latitude bands: about 100,000 triangles; closure point at the pole.
  run("dome", makeHemisphere(R, 448, 112), false, Vec3(0, 0, R), [&](const Polyline& l) {
    return R * std::acos(std::clamp(l.front().normalized().dot(l.back().normalized()), -1.0, 1.0));
  });
  return 0;
}
