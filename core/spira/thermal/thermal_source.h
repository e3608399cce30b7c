#pragma once

#include <vector>

#include "spira/thermal/thermal_mesh.h"
#include "spira/thermal/thermal_solver.h"

namespace spira {

// The energy (J) the moving arc puts into the nodes over a step. With no radius, the source's point
// load: along each heat segment the load is split linearly between its two ends by the torch's
// position (Eq. 5.28, with the weights the right way round). With a radius R, a Gaussian surface flux
// 3P / (pi R^2) exp(-3 d^2 / R^2) around the torch (95 % of the power within R), spread over the
// deposited nodes within 1.5 R by their share of the shell's area and normalised so the power is put
// in exactly; a mesh finer than R then no longer sets the peak and the pool. Either way the load is
// integrated over the time the torch spends on each segment, so no segment is skipped.
class SourceLoad {
 public:
  SourceLoad(const ThermalMesh& mesh, const ThermalSettings& settings);
  // Adds the energy of [t0, t1] into `energy` (per node) and returns its total.
  double add(double t0, double t1, const std::vector<char>& deposited, std::vector<double>& energy);

 private:
  // Spreads `joules` around `at`, on the segment from node a to node b.
  void spread(const Vec3& at, int a, int b, double joules, const std::vector<char>& deposited,
              std::vector<double>& energy);

  const ThermalMesh& mesh_;
  double power_, perWireFeed_, radius_;
  std::vector<std::array<double, 2>> table_;
  size_t segment_ = 0;
  std::vector<int> neighbourStart_, neighbours_;
  std::vector<double> area_;  // each node's third of its triangles' areas, mm2
  std::vector<int> mark_, stack_, found_;
  std::vector<double> weight_;
  int stamp_ = 0;
};

}  // namespace spira
