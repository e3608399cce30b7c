#pragma once

#include <array>
#include <vector>

#include "spira/thermal/thermal_material.h"
#include "spira/thermal/thermal_mesh.h"

namespace spira {

// Film coefficients and the air temperature of the source's boundary conditions
// (000_dbb97c2716e10cc3.txt §5.4.2): both faces of the shell lose heat to the air, the edges on the
// substrate to the (unmeshed) substrate.
struct ThermalFilms {
  double air = 35.0;             // W/(m2 K), each face
  double substrate = 2000.0;     // W/(m2 K), on the substrate edge times the thickness
  double airTemperature = 20.0;  // C
};

// The assembled capacity [C] and conductance [K] of the shell (SI: J/K and W/K) on one fixed sparsity
// pattern (both triangles stored, columns sorted per row), the convection load {F}, and the column sums
// of C and of the convection part of K that the energy balance needs. Every element starts with the
// inactive properties (lumped capacity) and no convection; activate() swaps in the active ones
// (Eq. 5.30), with a lumped or a consistent capacity.
class ThermalSystem {
 public:
  ThermalSystem(const ThermalMesh& mesh, const ThermalMaterial& material, const ThermalFilms& films,
                bool lumpedCapacity);

  void activate(int element);
  const std::array<int, 3>& nodesOf(int element) const { return elements_[size_t(element)].nodes; }
  bool active(int element) const { return active_[size_t(element)] != 0; }
  int size() const { return int(rowStart.size()) - 1; }

  std::vector<int> rowStart, column;
  std::vector<double> capacity, conductance;  // values of C and K
  std::vector<double> convectionLoad;         // F: film coefficient x air temperature, W
  std::vector<double> capacitySum;            // 1^T C, J/K per node
  std::vector<double> lossWeight;             // 1^T K_convection, W/K per node

 private:
  struct Element {
    std::array<int, 3> nodes;
    std::array<int, 9> position;       // of (a, b) in the pattern, a, b = 0..2 row-major
    double area = 0.0;                 // m2
    std::array<double, 9> gradient{};  // area * grad N_a . grad N_b
    int edgeA = -1, edgeB = -1;        // local indices of a substrate edge
    double edgeLength = 0.0;           // m
  };
  void add(const Element& e, double capacityScale, bool lumped, double conductivityScale, double faceFilm,
           double edgeFilm);

  std::vector<Element> elements_;
  std::vector<char> active_;
  ThermalMaterial material_;
  ThermalFilms films_;
  double thickness_ = 0.0;  // m
  bool lumped_ = true;
};

}  // namespace spira
