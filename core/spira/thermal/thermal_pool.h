#pragma once

#include <vector>

#include "spira/path/trajectory.h"
#include "spira/thermal/thermal_material.h"
#include "spira/thermal/thermal_mesh.h"
#include "spira/thermal/thermal_solver.h"

namespace spira {

// The weld pool's length in the moving frame (000_dbb97c2716e10cc3.txt §5.7, Fig. 5.20): at each
// step, the deposited nodes above melting that are connected to the torch's node, extended along
// their edges to where the melting isotherm crosses them, measured along the torch's travel
// direction (the trajectory point's tangent). Each trajectory point gets the length when the torch
// is over it; 0 when the torch's node is not molten (arc off, or a cold start).
class MeltPoolTracker {
 public:
  MeltPoolTracker(const ThermalMesh& mesh, const Trajectory& trajectory, double meltingTemperature);
  void operator()(const ThermalStep& step);
  const std::vector<double>& lengths() const { return lengths_; }  // mm, per trajectory point

 private:
  double lengthAt(size_t heatIndex, const ThermalStep& step);

  const ThermalMesh& mesh_;
  const Trajectory& trajectory_;
  double melt_;
  std::vector<int> neighbourStart_, neighbours_;
  std::vector<int> heatPoint_;  // heat index -> trajectory point starting its segment
  std::vector<double> lengths_;
  std::vector<int> mark_, stack_;
  int stamp_ = 0;
  size_t nextPoint_ = 0;
};

// The weighted Bond number of Eq. 5.31: gravity against surface tension on a pool of length L,
// weighted by exp(pi/4 - alpha/2) where alpha is the angle between the surface normal and the
// vertical (1 on a vertical wall, e^(pi/4) on a horizontal surface). L in mm, the normal unit.
double weightedBondNumber(const ThermalMaterial& material, double poolLength, const Vec3& normal);

// The source gives no threshold (Fig. 5.21). Bo = (L / l_c)^2 x weight, l_c = sqrt(sigma / (rho g))
// the capillary length (4.8 mm for the source's steel): 5 flags a pool 2.2 capillary lengths long
// (10.7 mm) on a vertical wall, or 1.5 on a horizontal surface. On the bundled dome the pool of the
// steady wall (7.5-8 mm) stays at 2.5-3.3; docs/thermal.md gives the distribution.
constexpr double kDefaultBondThreshold = 5.0;

}  // namespace spira
