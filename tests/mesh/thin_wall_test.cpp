// Wall thickness and mid-surface of closed solids, against shapes whose answer is known in closed
// form: a thin tube (thickness R - r, mid-surface radius (R + r) / 2), a solid cylinder and a
// thick-walled tube (bulk bodies).
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "mesh_test_shapes.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/mesh/thin_wall.h"

namespace spira::test {
namespace {

constexpr double kR = 40.0, kr = 36.0, kH = 60.0;

TEST(TubeSolid, IsOneWatertightOutwardPiece)
{
  const TriangleMesh tube = makeTubeSolid(kR, kr, kH, 96, 20);
  const MeshReport r = validateMesh(tube);
  EXPECT_TRUE(r.isPlannable()) << r.toText();
  EXPECT_TRUE(r.boundaryLoops.empty());
  EXPECT_EQ(r.componentCount, 1u);
  // The polygon's volume: the annulus of the two inscribed 96-gons times the height.
  const double polygon = 0.5 * 96 * std::sin(2.0 * M_PI / 96);
  EXPECT_NEAR(signedVolume(tube), polygon * (kR * kR - kr * kr) * kH, 1e-6 * kR * kR * kH);
}

TEST(ThinWall, TubeThicknessIsTheRadiusDifference)
{
  const ThinWallAnalysis a = analyseClosedSolid(makeTubeSolid(kR, kr, kH, 128, 24));
  ASSERT_EQ(a.kind, SolidKind::ThinWalled) << a.reason;
  // A ray from a facet of the outer 128-gon meets the inner one within R (1 - cos(pi / 128)) of R - r.
  EXPECT_NEAR(a.thickness.median, kR - kr, 0.02);
  EXPECT_NEAR(a.thickness.thinnest, kR - kr, 0.02);
  EXPECT_NEAR(a.thickness.thickest, kR - kr, 0.02);
  // The end annuli (ray along the wall) are the only faces left out.
  const double annuli = 2.0 * M_PI * (kR * kR - kr * kr);
  const double skins = 2.0 * M_PI * (kR + kr) * kH;
  EXPECT_NEAR(a.wallAreaFraction, skins / (skins + annuli), 0.01);
}

TEST(ThinWall, TubeMidSurfaceIsTheMiddleCylinderOpenAtBothEnds)
{
  const ThinWallAnalysis a = analyseClosedSolid(makeTubeSolid(kR, kr, kH, 128, 24));
  ASSERT_EQ(a.kind, SolidKind::ThinWalled) << a.reason;
  const TriangleMesh& mid = a.midSurface;
  const MeshReport r = validateMesh(mid);
  EXPECT_TRUE(r.isPlannable()) << r.toText();
  EXPECT_EQ(r.componentCount, 1u);
  ASSERT_EQ(r.boundaryLoops.size(), 2u);
  EXPECT_EQ(r.partClass, PartClass::Open);
  EXPECT_NEAR(r.boundaryLoops.front().zMin, 0.0, 1e-9);
  EXPECT_NEAR(r.boundaryLoops.back().zMax, kH, 1e-9);
  EXPECT_EQ(mid.faceCount(), 2u * 128u * 24u);  // the outer skin's faces, nothing else
  for (const Vec3& v : mid.vertices) EXPECT_NEAR(std::hypot(v.x(), v.y()), 0.5 * (kR + kr), 0.02);
  // Outward like the skin it came from.
  for (size_t f = 0; f < mid.faceCount(); f += 97) {
    const Face& t = mid.faces[f];
    const Vec3 c = (mid.vertices[t[0]] + mid.vertices[t[1]] + mid.vertices[t[2]]) / 3.0;
    EXPECT_GT(mid.faceNormal(f).dot(Vec3(c.x(), c.y(), 0.0)), 0.0);
  }
}

TEST(ThinWall, InsideOutExportIsMeasuredTheRightWayOut)
{
  TriangleMesh tube = makeTubeSolid(kR, kr, kH, 128, 24);
  for (Face& f : tube.faces) std::swap(f[1], f[2]);
  const ThinWallAnalysis a = analyseClosedSolid(tube);
  ASSERT_EQ(a.kind, SolidKind::ThinWalled) << a.reason;
  EXPECT_NEAR(a.thickness.median, kR - kr, 0.02);
  for (const Vec3& v : a.midSurface.vertices) EXPECT_NEAR(std::hypot(v.x(), v.y()), 0.5 * (kR + kr), 0.02);
}

TEST(ThinWall, SolidCylinderIsBulk)
{
  const double R = 30.0, H = 50.0;
  const ThinWallAnalysis a = analyseClosedSolid(makeRevolved({{0.0, 0.0}, {R, 0.0}, {R, H}, {0.0, H}}, 64));
  EXPECT_EQ(a.kind, SolidKind::Bulk) << a.reason;
  // Rays cross the diameter (side) or the height (caps): the median is one of the two.
  EXPECT_GT(a.thickness.median, 0.9 * std::min(2.0 * R, H));
  EXPECT_LT(a.thickness.median, 1.01 * std::max(2.0 * R, H));
  EXPECT_NE(a.reason.find("solid body"), std::string::npos) << a.reason;
  EXPECT_TRUE(a.midSurface.empty());
}

TEST(ThinWall, ThickWalledTubeIsBulk)
{
  // 30 mm of wall on a part 117 mm across its diagonal: a quarter of its size, not a thin wall.
  const ThinWallAnalysis a = analyseClosedSolid(makeTubeSolid(40.0, 10.0, 30.0, 96, 6));
  EXPECT_EQ(a.kind, SolidKind::Bulk) << a.reason;
  EXPECT_NEAR(a.thickness.median, 30.0, 0.2);
}

TEST(ThinWall, SteppedWallKeepsItsLedgeInTheSkin)
{
  // Outer skin steps in from R to R - 2 at mid-height (a groove above, like the corpus adaptor's):
  // the ledge's ray runs down the thick wall, yet the ledge belongs to the outer skin, so the
  // mid-surface stays one piece open at both ends.
  const double r = 30.0, R = 34.0, h = 40.0;
  std::vector<Eigen::Vector2d> profile;
  for (int i = 0; i <= 8; ++i) profile.emplace_back(r, h - h * i / 8.0);
  for (int i = 0; i <= 4; ++i) profile.emplace_back(R, 0.5 * h * i / 4.0);
  for (int i = 0; i <= 4; ++i) profile.emplace_back(R - 2.0, 0.5 * h + 0.5 * h * i / 4.0);
  const TriangleMesh m = makeRevolvedSolid(profile, 96);
  ASSERT_TRUE(validateMesh(m).boundaryLoops.empty());
  const ThinWallAnalysis a = analyseClosedSolid(m);
  ASSERT_EQ(a.kind, SolidKind::ThinWalled) << a.reason;
  EXPECT_NEAR(a.thickness.thinnest, 2.0, 0.05);
  EXPECT_NEAR(a.thickness.thickest, 4.0, 0.05);
  const MeshReport mid = validateMesh(a.midSurface);
  EXPECT_EQ(mid.componentCount, 1u);
  EXPECT_EQ(mid.boundaryLoops.size(), 2u) << mid.toText();
  // Away from the step, the mid-surface is half-way through the local wall.
  for (const Vec3& v : a.midSurface.vertices) {
    const double radius = std::hypot(v.x(), v.y());
    if (v.z() < 0.3 * h) {
      EXPECT_NEAR(radius, 0.5 * (r + R), 0.1) << v.transpose();
    } else if (v.z() > 0.7 * h) {
      EXPECT_NEAR(radius, 0.5 * (r + R - 2.0), 0.1) << v.transpose();
    }
  }
}

}  // namespace
}  // namespace spira::test
