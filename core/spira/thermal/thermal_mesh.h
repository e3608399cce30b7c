#pragma once

#include <array>
#include <vector>

#include "spira/base/transform.h"
#include "spira/path/trajectory.h"

namespace spira {

// How the shell mesh of the deposit is cut from the trajectory (000_dbb97c2716e10cc3.txt §5.3.3).
struct ThermalMeshSettings {
  int subSegments = 1;      // k: sub-segments per trajectory segment (Eq. 5.24)
  int divisions = 1;        // f: element rows across each layer (Eq. 5.25)
  double substrateZ = 0.0;  // mm: the substrate plane the first revolution rests on
  double thickness = 5.0;   // mm: shell thickness tau, the bead width
  // A path whose first revolution starts higher than this above the substrate (a branch on top of
  // an earlier path) rests on the nearest nodes of the earlier paths instead.
  double substrateContact = 10.0;  // mm
};

// A triangle shell of the deposit, nodes numbered in the order the torch creates them, so the
// nodes deposited by time t are a prefix (the solver solves only that prefix and its fringe).
// Positions in mm, times in s.
struct ThermalMesh {
  std::vector<Vec3> nodes;
  std::vector<std::array<int, 3>> triangles;
  std::vector<double> elementBirth;  // the time the torch starts the sub-segment that lays the element
  // The edge of an element lying on the substrate (L_substrat), or {-1, -1}.
  std::vector<std::array<int, 2>> substrateEdge;
  std::vector<int> substrateNodes;
  // The heat-source path L_chaleur: the trajectory points and the k - 1 points between each pair,
  // their nodes, the time the torch is there, and whether the arc is on from one to the next.
  std::vector<int> heatNode;
  std::vector<double> heatTime;
  std::vector<char> heatArcOn;       // heatArcOn[i]: segment i -> i + 1 carries heat (size heatNode - 1)
  std::vector<double> heatWireFeed;  // mm/s on segment i -> i + 1, for a power set per unit wire feed
  std::vector<int> pointHeatIndex;   // trajectory point -> its index in the heat path
  std::vector<int> pointBelowNode;   // trajectory point -> the node under it (previous layer or substrate)
  double thickness = 5.0;            // mm

  size_t nodeCount() const { return nodes.size(); }
  size_t elementCount() const { return triangles.size(); }
  double buildTime() const { return heatTime.empty() ? 0.0 : heatTime.back(); }
  // The node nearest to `p` (mm).
  int nearestNode(const Vec3& p) const;
};

// Each node's neighbours along the shell's edges: those of node v are
// neighbours[start[v] .. start[v + 1]), sorted.
struct NodeAdjacency {
  std::vector<int> start, neighbours;
};
NodeAdjacency nodeAdjacency(const ThermalMesh& mesh);

// Builds the shell: each revolution joined to the one before it (to the substrate plane for the
// first), k sub-segments along the path, f rows across, two triangles per quad where revolutions
// match point for point, and a zipper (fan at a closure point) where they do not.
// Paths (TrajectoryPoint::path) are laid one after the other; the moves between them carry no heat.
// Throws InputError for an empty trajectory, k or f below 1, a non-positive thickness, or a segment
// without a travel speed (a plan without process channels).
ThermalMesh buildThermalMesh(const Trajectory& trajectory, const ThermalMeshSettings& settings);

}  // namespace spira
