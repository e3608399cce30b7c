#pragma once

#include <memory>

#include "spira/document/document_state.h"

namespace spira::test {

// A small open mesh (a square tube, 8 faces) with awkward coordinates: 0.1, 1e-300, -0.0,
// the smallest denormal, the largest double, pi.
TriangleMesh awkwardMesh();
// A small closed mesh (tetrahedron) built by hand.
TriangleMesh tetrahedron(double edge);

Part samplePart();
CellRecord sampleCell();
// Every ParamValue type, with values that would change type or sign in a careless codec.
PlanSettings sampleSettings();
Trajectory sampleTrajectory(int points);
Generatrices sampleGeneratrices();
// A solved motion of `points` points with awkward values (kinematics_test_data.cpp).
KinematicsResult sampleKinematics(int points);
// A thermal stage result on `points` points: a strip of shell, NaN where a point has nothing below,
// two frames (the first before the last nodes are born), one probe and a re-planned path.
ThermalStageResult sampleThermal(int points);
// A state with every member set and every stage's result and report present.
DocumentState fullState();

// Bitwise equality of two vertex lists (== calls -0.0 and 0.0 equal).
bool bitwiseEqual(const std::vector<Vec3>& a, const std::vector<Vec3>& b);

}  // namespace spira::test
