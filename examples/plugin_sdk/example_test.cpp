// The worked example of docs/architecture.md, compiled and run in the test suite: a registry with
// the built-in plugins and the two example plugins plans an open cylinder with the example
// strategy and writes its path with the example exporter.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <string>

#include "builtin_plugins.h"
#include "examples/plugin_sdk/ruled_decomposer.h"
#include "examples/plugin_sdk/xyz_exporter.h"
#include "spira/base/progress.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/pipeline/export_job.h"
#include "spira/planning/planner.h"
#include "spira/plugin/plugin_registry.h"
#include "support/test_support.h"

namespace spira::example {
namespace {

PluginRegistry registryWithTheExamples()
{
  PluginRegistry registry;
  registerBuiltinPlugins(registry);
  registry.add(std::make_unique<RuledDecomposer>());
  registry.add(std::make_unique<XyzExporter>());
  return registry;
}

TEST(PluginSdkExample, TheRuledStrategyPlansACylinderAndTheXyzExporterWritesIt)
{
  const PluginRegistry registry = registryWithTheExamples();
  const TriangleMesh cylinder = makeOpenCylinder(40.0, 30.0, 120, 15);
  const MeshReport report = validateMesh(cylinder);
  PlanRequest request(cylinder, report);
  request.decomposerId = "decomposer.example_ruled";
  request.params["decomposer.example_ruled"].set("lines", std::int64_t{90});
  NullProgress progress;
  const PlanOutput plan = planPart(registry, request, progress);

  // 90 straight generatrices from z = 0 to z = 30 on the wall (radius 40, within the chord sag
  // of 120 facets: 40 (1 - cos(pi / 120)) = 0.014 mm).
  ASSERT_EQ(plan.generatrices.lines.size(), 90u);
  for (const Polyline& line : plan.generatrices.lines) {
    EXPECT_NEAR(line.front().z(), 0.0, 1e-9);
    EXPECT_NEAR(line.back().z(), 30.0, 1e-9);
    EXPECT_NEAR(line.front().head<2>().norm(), 40.0, 0.015);
  }
  // Every generatrix is 30 mm long: the spiral lays equal steps, 30 mm / n, inside the 1.8-2.2 window.
  EXPECT_TRUE(plan.feasible()) << plan.deposits.summary();
  EXPECT_NEAR(plan.spiral.report.stepMin, plan.spiral.report.stepMax, 1e-9);
  EXPECT_GE(plan.spiral.report.stepMin, 1.8);
  EXPECT_LE(plan.spiral.report.stepMax, 2.2);

  test::TempDir out;
  ExportJob job;
  job.exporterId = "export.example_xyz";
  job.header["part"] = "cylinder";
  const ExportOutcome exported =
      exportTrajectory(registry, plan.spiral.trajectory, job, out.path(), progress);
  ASSERT_EQ(exported.result.files.size(), 1u);
  std::ifstream in(exported.result.files[0]);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "# part: cylinder");
  size_t rows = 0;
  double x = 0, y = 0, z = 0, ts = 0;
  while (in >> x >> y >> z >> ts) {
    if (rows++ == 0) {  // the arc starts where the plan starts
      EXPECT_LT((Vec3(x, y, z) - plan.spiral.trajectory.points.front().position).norm(), 1e-6);
    }
    EXPECT_GT(ts, 0.0);
  }
  EXPECT_EQ(rows, exported.robotTargets);
}

TEST(PluginSdkExample, TheRuledStrategyRefusesAClosedPartWithItsReason)
{
  const PluginRegistry registry = registryWithTheExamples();
  std::string why;
  const TriangleMesh cylinder = makeOpenCylinder(40.0, 30.0, 60, 10);
  DecomposeInput input{cylinder, PartClass::Closed, {}, std::nullopt, std::nullopt, nullptr, {}};
  EXPECT_FALSE(registry.decomposer("decomposer.example_ruled").accepts(input, &why));
  EXPECT_EQ(why, "the ruled example needs an open wall with a lower and an upper edge");
}

}  // namespace
}  // namespace spira::example
