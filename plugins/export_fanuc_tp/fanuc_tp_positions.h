#pragma once

#include <array>
#include <string>

#include "spira/base/transform.h"

namespace spira {

// The /POS entries of a FANUC TP (.ls) program, in the layout the controller itself writes.
struct TpPositionFrames {
  int uframe = 0;
  int utool = 1;
  bool positioner = false;  // adds a GP2 group with the two positioner axes
};

// P[index] with a Cartesian GP1 (XYZ in mm, WPR in degrees from the full rotation matrix) and
// the CONFIG string.
void appendCartesianPosition(std::string& out, size_t index, const Transform& pose, const std::string& config,
                             const std::array<double, 2>& externalDeg, const TpPositionFrames& frames);

// P[index] with a joint GP1 (J1..J6 in the controller's degrees).
void appendJointPosition(std::string& out, size_t index, const std::array<double, 6>& jointsDeg,
                         const std::array<double, 2>& externalDeg, const TpPositionFrames& frames);

// True for a TP configuration string such as "N U T, 0, 0, 0": wrist N|F, elbow U|D, base T|B,
// then three integer turn numbers (J1, J4, J6).
bool isValidTpConfig(const std::string& config);

}  // namespace spira
