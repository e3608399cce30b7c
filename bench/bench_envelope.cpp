// Envelope projection and the curve skeleton on ~100,000-triangle analytic parts.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "best_of.h"
#include "builtin_plugins.h"
#include "decomposer_envelope/envelope_projection.h"
#include "spira/base/units.h"
#include "spira/contour/contour_loop.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/plugin/plugin_registry.h"
#include "spira/skeleton/mcf_skeleton.h"

namespace {

using namespace spira;

// The largest relative error of the generatrix lengths against `expected(m)`.
double worstError(const Generatrices& g, const std::function<double(size_t)>& expected)
{
  double worst = 0;
  for (size_t m = 0; m < g.lines.size(); ++m)
    worst = std::max(worst, std::abs(polylineLength(g.lines[m], false) - expected(m)) / expected(m));
  return worst;
}

void projection(const char* name, const TriangleMesh& mesh, const std::function<double(size_t)>& expected)
{
  const MeshReport report = validateMesh(mesh);
  EnvelopeOptions options;
  options.generatrixCount = 360;
  NullProgress progress;
  EnvelopeDecomposition d;
  const double t = bestOf(3, [&] {
    d = decomposeByEnvelopeProjection(mesh, report.boundaryLoops[0], report.boundaryLoops[1],
                                      ProjectionAxis::vertical(Vec3::Zero()), options, progress);
  });
  std::printf(
      "%-14s %7zu faces  projection (360 generatrices x %zu points, %zu rays) %7.1f ms  "
      "max length error %.4f %%\n",
      name, mesh.faceCount(), d.generatrices.lines[0].size(), d.raysCast, 1e3 * t,
      100 * worstError(d.generatrices, expected));

  // The plugin end to end with the default axis: skeleton, then projection.
  const DecomposerPlugin& plugin = builtinRegistry().decomposer("decomposer.envelope_projection");
  DecomposeInput in{mesh, report.partClass, report.boundaryLoops[0], report.boundaryLoops[1], std::nullopt};
  DecomposeResult res;
  const double tp = bestOf(1, [&] { res = plugin.decompose(in, ParamSet{}, progress); });
  std::printf(
      "%-14s plugin, axis=auto (skeleton + projection)                       %7.1f ms  "
      "max length error %.4f %%\n",
      "", 1e3 * tp, 100 * worstError(res.generatrices, expected));
}

void skeleton(const char* name, const TriangleMesh& mesh, double radius)
{
  NullProgress progress;
  SkeletonResult r;
  const double t = bestOf(1, [&] { r = computeCurveSkeleton(mesh, SkeletonOptions{}, progress); });
  double offAxis = 0;
  for (const Polyline& b : r.skeleton.branches)
    for (const Vec3& p : b) offAxis = std::max(offAxis, std::hypot(p.x(), p.y()));
  std::printf(
      "%-14s %7zu faces  skeleton %7.1f ms  (%zu faces contracted, %zu steps%s, %zu nodes, %zu branch(es), "
      "%zu branch point(s), monotone %s, max off-axis %.2f %% of R)\n",
      name, mesh.faceCount(), 1e3 * t, r.facesContracted, r.iterations, r.converged ? "" : ", not converged",
      r.skeleton.graph.nodes.size(), r.skeleton.branchCount(), r.skeleton.branchPoints.size(),
      r.skeleton.monotoneInZ ? "yes" : "no", 100 * offAxis / radius);
}

}  // namespace

int main()
{
  // ~100,000 triangles each: 400 segments x 125 rings x 2.
  const double R = 40, H = 100;
  const TriangleMesh tube = makeOpenCylinder(R, H, 400, 125);
  projection("cylinder", tube, [&](size_t) { return H; });
  const TriangleMesh cone = makeOpenCone(R, 0.7 * R, H, 400, 125);
  const double slant = std::hypot(H, 0.3 * R);
  projection("truncated cone", cone, [&](size_t) { return slant; });
  // Sloped rim z = 80 + x tan 20 deg: generatrix m at angle 2 pi m / 360 is 80 + R cos tan 20 long.
  TriangleMesh sloped = makeOpenCylinder(R, 1.0, 400, 125);
  const double tilt = std::tan(degToRad(20));
  for (Vec3& v : sloped.vertices) v.z() *= 80 + v.x() * tilt;
  projection("sloped rim", sloped, [&](size_t m) { return 80 + R * std::cos(2 * kPi * m / 360.0) * tilt; });

  skeleton("cylinder", tube, R);
  skeleton("truncated cone", cone, R);
  return 0;
}
