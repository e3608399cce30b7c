#include <gtest/gtest.h>

#include "contour_shapes.h"
#include "spira/contour/branch_detection.h"
#include "spira/mesh/mesh_primitives.h"

namespace spira {
namespace {

std::vector<double> evenLevels(double from, double step, int count)
{
  std::vector<double> v;
  for (int i = 0; i < count; ++i) v.push_back(from + step * i);
  return v;
}

TEST(BranchDetection, TwoTubesSplitAndMergeAtTheRightLevels)
{
  // Tube A from z = 0 to 10, tube B beside it from z = 5 to 15: one contour, then two, then one.
  const TriangleMesh a = makeOpenCylinder(5, 10, 40, 10);
  const TriangleMesh b = test::translated(makeOpenCylinder(5, 10, 40, 10), Vec3(20, 0, 5));
  const TriangleMesh mesh = test::merged(a, b);
  const auto levels = extractIsoContours(mesh, test::heightField(mesh), evenLevels(0.25, 0.5, 30));
  const auto counts = contourCounts(levels);
  for (size_t k = 0; k < levels.size(); ++k) {
    const double c = levels[k].value;
    EXPECT_EQ(counts[k], (c > 5 && c < 10) ? 2u : 1u) << "level " << c;
  }
  const auto changes = findBranchChanges(levels);
  ASSERT_EQ(changes.size(), 2u);
  EXPECT_DOUBLE_EQ(changes[0].value, 5.25);
  EXPECT_EQ(changes[0].levelIndex, 10u);
  EXPECT_EQ(changes[0].before, 1u);
  EXPECT_EQ(changes[0].after, 2u);
  EXPECT_TRUE(changes[0].splits());
  EXPECT_NEAR(changes[0].meanZ, 5.25, 1e-9);
  EXPECT_DOUBLE_EQ(changes[1].value, 10.25);
  EXPECT_EQ(changes[1].before, 2u);
  EXPECT_EQ(changes[1].after, 1u);
  EXPECT_FALSE(changes[1].splits());
}

TEST(BranchDetection, FlatForkSplitsAboveItsCrotch)
{
  const TriangleMesh mesh = test::flatFork();
  std::vector<double> y;
  for (const auto& v : mesh.vertices) y.push_back(v.y());
  // 4.5, 4.75, 5.0 (exactly on the crotch's row of vertices), 5.25, ...
  const auto levels = extractIsoContours(mesh, y, evenLevels(4.5, 0.25, 8));
  const auto changes = findBranchChanges(levels);
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_DOUBLE_EQ(changes[0].value, 5.25);
  EXPECT_EQ(changes[0].before, 1u);
  EXPECT_EQ(changes[0].after, 2u);
  EXPECT_EQ(contourCounts(levels)[2], 1u);  // the level through the crotch's vertices: still one
}

TEST(BranchDetection, MonoBranchPartHasNoChange)
{
  const TriangleMesh mesh = makeHemisphere(20, 64, 16);
  const auto levels = extractIsoContours(mesh, test::hemisphereDistance(mesh, 20), evenLevels(0.3, 0.6, 52));
  EXPECT_TRUE(findBranchChanges(levels).empty());
  for (size_t n : contourCounts(levels)) EXPECT_EQ(n, 1u);
}

}  // namespace
}  // namespace spira
