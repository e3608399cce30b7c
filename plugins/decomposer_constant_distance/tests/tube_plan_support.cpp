#include "tube_plan_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "builtin_plugins.h"
#include "spira/base/progress.h"
#include "spira/base/segment_distance.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"

namespace spira::test {

TriangleMesh quarterTorus()
{
  const double bend = 50.0, r = 15.0, angle = 0.5 * 3.14159265358979323846;
  return makeBentTube(bend, r, angle, segmentsForEdge(r, 2.0), int(bend * angle / 2.0));
}

namespace {

PlanOutput planWithValues(const std::string& decomposerId, const TriangleMesh& mesh, double h, double hMin,
                          double hMax, int points, const std::map<std::string, std::string>& values,
                          const TriangleMesh* substrate = nullptr)
{
  const MeshReport report = validateMesh(mesh);
  PlanRequest request(mesh, report);
  if (substrate)
    request.substrate = std::make_shared<const SubstrateSurface>(SubstrateSurface::mesh(*substrate));
  request.decomposerId = decomposerId;
  request.params["spiral"].set("h", h);
  request.params["spiral"].set("h_min", hMin);
  request.params["spiral"].set("h_max", hMax);
  if (points > 0) request.params[decomposerId].set("points_per_rev", std::int64_t{points});
  for (const auto& [key, value] : values)
    if (!value.empty()) request.params[decomposerId].set(key, value);
  NullProgress progress;
  return planPart(builtinRegistry(), request, progress);
}

}  // namespace

PlanOutput planWith(const std::string& decomposerId, const TriangleMesh& mesh, double h, double hMin,
                    double hMax, int points)
{
  return planWithValues(decomposerId, mesh, h, hMin, hMax, points, {});
}

double distanceToClosed(const Vec3& p, const std::vector<Vec3>& loop)
{
  double best = 1e300;
  for (size_t j = 0; j < loop.size(); ++j)
    best = std::min(best, pointSegmentDistance(p, loop[j], loop[(j + 1) % loop.size()]));
  return best;
}

size_t expectFlagsOnlyAtFolds(const PlanOutput& plan, double bendRadius)
{
  EXPECT_TRUE(plan.layers);
  if (!plan.layers) return 0;
  const Trajectory& t = plan.spiral.trajectory;
  for (const DepositFlag& f : plan.deposits.flags) {
    EXPECT_EQ(f.kind, DepositDefect::BelowDeposit) << "point " << f.point;
    const TrajectoryPoint& p = t.points[f.point];
    const Vec3& x = p.position;
    EXPECT_GT(std::hypot(x.x() + bendRadius, x.z()), bendRadius)
        << "point " << f.point << " on the inner side";
    // The spiral's revolution k lies between layers k and k + 1 (and their kinks).
    const std::vector<double>& kinks = plan.layers->kinkDeg;
    const size_t k = std::min(size_t(p.revolution), kinks.size() - 1);
    const double kink = std::max(kinks[k], kinks[std::min(k + 1, kinks.size() - 1)]);
    EXPECT_GT(kink, 90.0) << "point " << f.point << " of revolution " << p.revolution;
  }
  return plan.deposits.flags.size();
}

PlanOutput planTubeOn(const TriangleMesh& mesh, const TriangleMesh& substrate, double h, double hMin,
                      double hMax, const std::string& output, int points)
{
  return planWithValues("decomposer.constant_distance", mesh, h, hMin, hMax, points, {{"output", output}},
                        &substrate);
}

PlanOutput planTube(const TriangleMesh& mesh, double h, double hMin, double hMax, const std::string& output,
                    const std::string& end, const std::string& guide, int points)
{
  return planWithValues("decomposer.constant_distance", mesh, h, hMin, hMax, points,
                        {{"output", output}, {"end", end}, {"guide", guide}});
}

}  // namespace spira::test
