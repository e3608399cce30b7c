// The moving source against Rosenthal's thin-plate solution with surface losses (Rosenthal 1946;
// Rykalin's form with face losses, as in Carslaw & Jaeger's moving line source): the quasi-steady
// field of a line source q moving at v through a plate of thickness d, losing h on both faces, is
//   T - T0 = q / (2 pi k d) exp(-v xi / (2 a)) K0(r sqrt((v / 2a)^2 + 2 h / (k d)))
// with xi the distance ahead of the source and r the distance to it. On the top edge of a wall,
// an insulated edge, the image source doubles it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "spira/base/progress.h"
#include "spira/thermal/thermal_solver.h"
#include "thermal/thermal_cases.h"

namespace spira {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(ThermalVerification, QuasiSteadyFieldUnderTheTorchIsRosenthalsThinPlate)
{
  const double radius = 100.0, layer = 2.0, speed = 6.0, power = 1000.0;
  const int below = 30, perRevolution = 314;
  // A wall of 30 revolutions laid cold (arc off, quickly), then one revolution with the arc on along
  // its top edge: the plate reaches 60 mm under the torch, ten times the field's decay length.
  Trajectory t = test::cylinderWall(radius, below + 1, perRevolution, layer, speed);
  for (TrajectoryPoint& p : t.points)
    if (p.revolution < below) {
      p.arcOn = false;
      p.travelSpeed = 600.0;
    }
  ThermalMeshSettings ms;
  ms.thickness = 5.0;
  ms.subSegments = 2;
  ms.divisions = 2;
  const ThermalMesh mesh = buildThermalMesh(t, ms);
  ThermalSettings s;
  s.power = power;
  s.activateAll = true;  // the plate ahead of the torch exists, as in the closed form
  s.films.substrate = 0.0;
  s.timeStep = 0.05;
  const double top = layer * (below + 1);
  const double probeAngle = 1.5 * kPi;  // three quarters of the way round
  const std::vector<double> depths = {3.0, 6.0, 9.0, 12.0};
  for (double d : depths)
    s.probePositions.push_back(Vec3(radius * std::cos(probeAngle), radius * std::sin(probeAngle), top - d));
  NullProgress progress;
  const ThermalResult r = simulateThermal(mesh, s, progress);

  const ThermalMaterial& m = s.material;
  const double a = m.conductivity / m.volumetricHeat();  // m2/s
  const double k = m.conductivity, plate = ms.thickness * 1e-3, v = speed * 1e-3;
  const double decay = std::sqrt(std::pow(v / (2.0 * a), 2) + 2.0 * s.films.air / (k * plate));
  const double start = mesh.heatTime[size_t(mesh.pointHeatIndex[size_t(below * perRevolution)])];
  int compared = 0;
  double worstBehind = 0.0, worstAhead = 0.0;  // behind or beside the torch; ahead of it
  for (size_t p = 0; p < r.probeNodes.size(); ++p) {
    const Vec3 at = mesh.nodes[size_t(r.probeNodes[p])];
    const double probeArc = radius * std::fmod(std::atan2(at.y(), at.x()) + 2.0 * kPi, 2.0 * kPi);
    const double depth = (top - at.z()) * 1e-3;
    for (size_t i = 0; i < r.probeTimes.size(); ++i) {
      const double travelled = speed * (r.probeTimes[i] - start);  // mm along the top edge
      if (travelled < 200.0) continue;                             // not yet quasi-steady
      const double ahead = (probeArc - travelled) * 1e-3, distance = std::hypot(ahead, depth);
      if (distance < 6e-3 || distance > 30e-3) continue;  // near the source the point load is no line source
      const double rise = 2.0 * power / (2.0 * kPi * k * plate) * std::exp(-v * ahead / (2.0 * a)) *
                          std::cyl_bessel_k(0.0, distance * decay);
      // Far ahead the rise falls under a degree, where a relative error says nothing.
      if (rise < 20.0) continue;
      const double error = std::abs(r.probeTemperatures[p][i] - 20.0 - rise) / rise;
      double& worst = ahead > 0.0 ? worstAhead : worstBehind;
      worst = std::max(worst, error);
      ++compared;
    }
  }
  EXPECT_GT(compared, 200);
  // Ahead of the torch the field falls as exp(-v xi / 2a), 5.5 mm per e-fold, on 1 mm elements.
  EXPECT_LT(worstBehind, 0.01);
  EXPECT_LT(worstAhead, 0.05);
  std::printf(
      "Rosenthal thin plate: %d samples 6-30 mm from the torch (rise > 20 K), worst error of the "
      "rise %.2f %% behind or beside it, %.2f %% ahead\n",
      compared, 100.0 * worstBehind, 100.0 * worstAhead);
}

}  // namespace
}  // namespace spira
