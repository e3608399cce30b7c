#pragma once

#include <optional>
#include <vector>

#include "spira/base/progress.h"
#include "spira/kinematics/arm_ik.h"

namespace spira {

// One solved pose of a tracked path.
struct TrackedPose {
  JointVector q = JointVector::Zero();  // URDF joints, rad; the previous pose's q when unreachable
  bool reachable = false;               // the configuration reaches the pose (within 1e-6 mm and 1e-8 rad)
  double limitMargin = 0.0;             // rad, against the IK's limits (ArmIk::axisMargins); < 0 outside
  double dexterity = 0.0;               // dexterity.h, 0 at a singularity
  double jointStep = 0.0;               // largest |q_j - previous q_j|, rad (from the seed at the first pose)
};

struct PathTrack {
  ArmConfiguration configuration;
  std::vector<TrackedPose> poses;
  size_t unreachable = 0;
  size_t outsideLimits = 0;
  double minDexterity = 1.0;
  double minLimitMargin = 0.0;  // rad
  double maxJointStep = 0.0;    // rad, over the whole path
};

// Solves a path of TCP poses T_base_tcp for a tool whose TCP is T_flange_tcp in the chain's tip
// frame (tool0): every pose in ONE configuration (given, or that of `seed`), each joint on the
// 2 pi branch nearest the previous pose's (the seed's for the first), so joints 1, 4 and 6 unwind
// continuously and the arm never flips inside the path. A pose the configuration cannot reach is
// reported and skipped (its q repeats the previous one). Calls progress.checkCancel(). Throws
// InputError naming the first pose that holds NaN or infinity (nothing is solved then).
PathTrack trackPath(const ArmIk& ik, const std::vector<Transform>& baseTcp, const Transform& flangeTcp,
                    const JointVector& seed, const std::optional<ArmConfiguration>& configuration,
                    Progress& progress);

}  // namespace spira
