#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/collision/basic_shapes.h"
#include "spira/collision/capsule_bvh.h"
#include "spira/collision/gjk.h"
#include "spira/collision/torch_solid.h"
#include "spira/path/tool_frame.h"

namespace spira {
namespace {

// The TCP at `tcp` with the build direction b = `build`: the torch body lies along +build.
Transform tcpFrame(const Vec3& tcp, const Vec3& build)
{
  TrajectoryPoint p;
  p.position = tcp;
  p.build = build.normalized();
  p.tangent = p.build.unitOrthogonal();
  p.normal = p.tangent.cross(p.build);
  return toolFrame(p);
}

// Distance from (r, z) to the torch's half cross-section, the polygon (0,s0) (rn,s0) (rb,s1) (rb,s2)
// (0,s2), for a point outside it: the profile a vertical torch sweeps about its axis.
double profileDistance(double r, double z, const TorchParams& p)
{
  using V2 = Eigen::Vector2d;
  const double s0 = p.standoff, s1 = s0 + p.coneLength, s2 = s1 + p.bodyLength;
  const V2 poly[5] = {V2(0, s0), V2(p.nozzleRadius, s0), V2(p.bodyRadius, s1), V2(p.bodyRadius, s2),
                      V2(0, s2)};
  const V2 x(r, z);
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 5; ++k) {
    const V2 a = poly[k], b = poly[(k + 1) % 5];
    const double t = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + t * (b - a) - x).norm());
  }
  return best;
}

TEST(TorchSolid, LiesAlongTheBuildDirectionFromTheStandoff)
{
  const TorchParams p;
  const TorchSolid torch(p, tcpFrame(Vec3(1, 2, 3), Vec3::UnitZ()));
  EXPECT_NEAR((torch.axis() - Vec3::UnitZ()).norm(), 0.0, 1e-15);
  EXPECT_NEAR((torch.tipCenter() - Vec3(1, 2, 18)).norm(), 0.0, 1e-12);
  const BoundingBox box = torch.bounds();
  EXPECT_NEAR((box.min - Vec3(1 - 20, 2 - 20, 18)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((box.max - Vec3(1 + 20, 2 + 20, 3 + 195)).norm(), 0.0, 1e-12);
  // Support points: the top rim upwards, the tip rim downwards (off-axis direction), the body side.
  EXPECT_NEAR(torch.support(Vec3(0, 0, 1)).z(), 198.0, 1e-12);
  EXPECT_NEAR(torch.support(Vec3(0.01, 0, -1)).z(), 18.0, 1e-12);
  EXPECT_NEAR(torch.support(Vec3(0.01, 0, -1)).x(), 9.0, 1e-12);
  EXPECT_NEAR(torch.support(Vec3(1, 0, 0)).x(), 21.0, 1e-12);
}

TEST(TorchSolid, HeightAboveAPlaneMatchesTheLowestRimWhenTilted)
{
  const TorchParams p;
  const double H = 4.0;
  for (const double deg : {0.0, 10.0, 30.0, 60.0, 85.0}) {
    const double a = degToRad(deg);
    const TorchSolid torch(p, tcpFrame(Vec3(7, -3, H), Vec3(std::sin(a), 0, std::cos(a))));
    const double s0 = p.standoff, s1 = s0 + p.coneLength, s2 = s1 + p.bodyLength;
    // The lowest point of a tilted circle of radius r at axial station s is H + s cos a - r sin a.
    const double expected = std::min({H + s0 * std::cos(a) - p.nozzleRadius * std::sin(a),
                                      H + s1 * std::cos(a) - p.bodyRadius * std::sin(a),
                                      H + s2 * std::cos(a) - p.bodyRadius * std::sin(a)});
    EXPECT_NEAR(torch.heightAbove(Vec3(0, 0, 0), Vec3::UnitZ()), expected, 1e-12) << deg << " deg";
  }
}

TEST(TorchSolid, DistancesToCapsulesMatchTheAnalyticProfile)
{
  const TorchParams p;
  const TorchSolid torch(p, tcpFrame(Vec3::Zero(), Vec3::UnitZ()));
  // A vertical capsule beside the body: the gap between two parallel cylinders.
  for (const double D : {25.0, 31.5, 80.0}) {
    const CapsuleBvh one({Capsule{Vec3(D, 0, 60), Vec3(D, 0, 150), 3.0}});
    EXPECT_NEAR(one.nearest(torch).distance, D - 20.0 - 3.0, 1e-6) << D;
  }
  // A horizontal capsule under the nozzle: the gap to the tip disc.
  const CapsuleBvh below({Capsule{Vec3(-50, 0, 5), Vec3(50, 0, 5), 2.0}});
  EXPECT_NEAR(below.nearest(torch).distance, 15.0 - 5.0 - 2.0, 1e-6);
  // Small spheres (zero-length capsules) around the cone, the shoulder and the top.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> ur(0.0, 40.0), uz(0.0, 210.0), uphi(0.0, 2.0 * kPi);
  int tested = 0;
  while (tested < 200) {
    const double r = ur(rng), z = uz(rng), phi = uphi(rng);
    const double d = profileDistance(r, z, p);
    const bool inside =
        z > p.standoff && z < 195.0 && r < p.bodyRadius &&
        (z >= 45.0 || r < p.nozzleRadius + (p.bodyRadius - p.nozzleRadius) * (z - 15.0) / 30.0);
    if (inside || d < 0.6) continue;
    const Vec3 c(r * std::cos(phi), r * std::sin(phi), z);
    const CapsuleBvh sphere({Capsule{c, c, 0.5}});
    EXPECT_NEAR(sphere.nearest(torch).distance, d - 0.5, 1e-5) << "r " << r << " z " << z;
    ++tested;
  }
}

TEST(TorchSolid, RejectsANozzleWiderThanTheBody)
{
  TorchParams p;
  p.nozzleRadius = 25.0;
  EXPECT_THROW(validateTorchParams(p), InputError);
  p = TorchParams();
  p.standoff = -1.0;
  EXPECT_THROW(validateTorchParams(p), InputError);
  EXPECT_NO_THROW(validateTorchParams(TorchParams()));
}

}  // namespace
}  // namespace spira
