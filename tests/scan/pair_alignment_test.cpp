// Alignment from picked point pairs: the rigid motion of exact pairs, refusals of pairs that cannot
// fix it, and a scan far off the part's frame brought onto it by pairs and ICP.
#include <gtest/gtest.h>

#include "builtin_plugins.h"

#include <random>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/io/import_service.h"
#include "spira/scan/pair_alignment.h"
#include "spira/scan/scan_alignment.h"
#include "spira/scan/scan_simulator.h"
#include "support/test_support.h"

namespace spira {
namespace {

Transform farOff()
{
  Transform T = Transform::Identity();
  T.linear() = Eigen::AngleAxisd(degToRad(130.0), Vec3(0.2, 0.1, 1.0).normalized()).toRotationMatrix();
  T.translation() = Vec3(420.0, -250.0, 35.0);
  return T;
}

double angleDeg(const Transform& T)
{
  return radToDeg(Eigen::AngleAxisd(T.linear()).angle());
}

std::string messageOf(const std::function<void()>& fn)
{
  try {
    fn();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PairAlignment, ExactPairsGiveTheMotionBack)
{
  const Transform T_scan_part = farOff();
  std::vector<PointPair> pairs;
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(80, 0, 10), Vec3(0, 60, 40), Vec3(30, 30, 90)})
    pairs.push_back({p, T_scan_part * p});
  const PairFit fit = fitPointPairs(pairs, 5.0);
  const Transform error = fit.T_part_scan * T_scan_part;
  EXPECT_LT(error.translation().norm(), 1e-9);
  EXPECT_LT(angleDeg(error), 1e-9);
  EXPECT_LT(fit.rmsMm, 1e-9);
  ASSERT_EQ(fit.residualsMm.size(), 4u);
}

TEST(PairAlignment, PairsThatCannotFixTheMotionAreRefused)
{
  const Transform T = farOff();
  const auto pairOf = [&](const Vec3& p) { return PointPair{p, T * p}; };
  EXPECT_NE(messageOf([&] {
              fitPointPairs({pairOf(Vec3(0, 0, 0)), pairOf(Vec3(50, 0, 0))}, 5.0);
            }).find("needs three pairs, 2 given"),
            std::string::npos);
  // Three picks along one edge leave the turn about it free.
  EXPECT_NE(messageOf([&] {
              fitPointPairs({pairOf(Vec3(0, 0, 0)), pairOf(Vec3(50, 0, 0)), pairOf(Vec3(100, 0.5, 0))}, 5.0);
            }).find("nearly on one line"),
            std::string::npos);
  // The third scan point picked 12 mm from its place: no rigid motion matches.
  std::vector<PointPair> wrong = {pairOf(Vec3(0, 0, 0)), pairOf(Vec3(80, 0, 0)), pairOf(Vec3(0, 60, 0)),
                                  pairOf(Vec3(80, 60, 30))};
  wrong[2].scan += Vec3(12.0, 0.0, 0.0);
  const std::string message = messageOf([&] { fitPointPairs(wrong, 5.0); });
  EXPECT_NE(message.find("do not match by one rigid motion: pair 3"), std::string::npos) << message;
}

TEST(PairAlignment, PairsAreReadFromTextWithHeaderAndComments)
{
  const auto pairs = parsePointPairs(
      "part_x,part_y,part_z,scan_x,scan_y,scan_z\n# picked in the viewer\n1,2,3,4,5,6\n\n7 8 9\t10 11 12 # "
      "b\n",
      "'pairs.csv'");
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[1].part, Vec3(7, 8, 9));
  EXPECT_EQ(pairs[1].scan, Vec3(10, 11, 12));
  const std::string message = messageOf([] { parsePointPairs("1,2,3,4,5,6\n1,2,3,4,5\n", "'pairs.csv'"); });
  EXPECT_NE(message.find("'pairs.csv', line 2: '1,2,3,4,5' is not six numbers"), std::string::npos)
      << message;
}

// A scan in the scanner's own frame, 130 deg and half a metre off the part: ICP alone from the
// identity cannot find it; three pairs picked about 0.3 mm off their places start it close enough.
TEST(PairAlignment, AScanFarOffIsBroughtOnByPickedPairsAndIcp)
{
  NullProgress progress;
  const TriangleMesh part =
      importPart(builtinRegistry(), test::sourceDir() / "tests/data/real/junction_waam_mm.stl", nullptr,
                 progress)
          .mesh;
  ScanErrors errors;
  errors.noiseMm = 0.05;
  errors.misalignment = farOff();
  const PointCloud scan = simulateSurfaceScan(part, 0.7, errors, 3);

  bool identityFailed = false;
  try {
    const AlignResult blind = alignScan(scan, part, Transform::Identity(), AlignSettings{}, progress);
    identityFailed = (blind.T_part_scan * errors.misalignment).translation().norm() > 1.0;
  } catch (const InputError&) {
    identityFailed = true;
  }
  EXPECT_TRUE(identityFailed);

  const BoundingBox box = part.bounds();
  std::mt19937 rng(11);
  std::normal_distribution<double> hand(0.0, 0.3);
  std::vector<PointPair> pairs;
  for (const Vec3& corner : {box.min, Vec3(box.max.x(), box.min.y(), box.min.z()), box.max}) {
    size_t nearest = 0;
    for (size_t v = 0; v < part.vertices.size(); ++v)
      if ((part.vertices[v] - corner).norm() < (part.vertices[nearest] - corner).norm()) nearest = v;
    const Vec3 p = part.vertices[nearest];
    pairs.push_back({p, errors.misalignment * p + Vec3(hand(rng), hand(rng), hand(rng))});
  }
  const PairFit start = fitPointPairs(pairs, 5.0);
  const Transform startError = start.T_part_scan * errors.misalignment;
  EXPECT_GT(startError.translation().norm() + angleDeg(startError), 0.05);  // picks alone are rough

  const AlignResult fit = alignScan(scan, part, start.T_part_scan, AlignSettings{}, progress);
  const Transform error = fit.T_part_scan * errors.misalignment;
  std::printf("from pairs %.3f mm %.3f deg off; after ICP %.4f mm %.4f deg\n",
              startError.translation().norm(), angleDeg(startError), error.translation().norm(),
              angleDeg(error));
  EXPECT_LT(error.translation().norm(), 0.02);
  EXPECT_LT(angleDeg(error), 0.02);
}

}  // namespace
}  // namespace spira
