#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cmath>
#include <string>

#include "spira/base/error.h"
#include "spira/thermal/thermal_solver.h"

namespace spira {

double arcPower(double voltage, double current, double efficiency)
{
  if (!(voltage > 0.0) || !(current > 0.0))
    throw InputError("arc voltage and current must be positive", "give U in V and I in A, or the power in W");
  if (!(efficiency > 0.0 && efficiency <= 1.0))
    throw InputError("arc efficiency must be in (0, 1], got " + std::to_string(efficiency),
                     "about 0.8 for GMAW/CMT");
  return efficiency * voltage * current;
}

std::vector<double> solveSteadyThermal(const ThermalMesh& mesh, const ThermalSettings& settings,
                                       const std::vector<std::pair<int, double>>& fixed)
{
  validateThermalMaterial(settings.material);
  ThermalSystem system(mesh, settings.material, settings.films, !settings.consistentCapacity);
  for (int e = 0; e < int(mesh.elementCount()); ++e) system.activate(e);
  const int n = system.size();
  std::vector<double> t(size_t(n), settings.films.airTemperature);
  std::vector<int> unknown(size_t(n), 0);
  for (const auto& [node, value] : fixed) {
    if (node < 0 || node >= n) throw InputError("fixed node " + std::to_string(node) + " is not in the mesh");
    t[size_t(node)] = value;
    unknown[size_t(node)] = -1;
  }
  int m = 0;
  for (int& u : unknown)
    if (u == 0) u = m++;
  // K T = F on the free nodes, the fixed ones moved to the right-hand side.
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m);
  for (int r = 0; r < n; ++r) {
    const int ur = unknown[size_t(r)];
    if (ur < 0) continue;
    rhs[ur] += system.convectionLoad[size_t(r)];
    for (int p = system.rowStart[size_t(r)]; p < system.rowStart[size_t(r) + 1]; ++p) {
      const int c = system.column[size_t(p)];
      const double k = system.conductance[size_t(p)];
      if (unknown[size_t(c)] < 0)
        rhs[ur] -= k * t[size_t(c)];
      else
        entries.emplace_back(ur, unknown[size_t(c)], k);
    }
  }
  Eigen::SparseMatrix<double> k(m, m);
  k.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(k);
  if (ldlt.info() != Eigen::Success)
    throw InputError(
        "the steady thermal problem has no unique solution",
        "fix the temperature of at least one node on every connected part, or give film coefficients");
  const Eigen::VectorXd x = ldlt.solve(rhs);
  for (int v = 0; v < n; ++v)
    if (unknown[size_t(v)] >= 0) t[size_t(v)] = x[unknown[size_t(v)]];
  return t;
}

}  // namespace spira
