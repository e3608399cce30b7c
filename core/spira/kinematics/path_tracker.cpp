#include "spira/kinematics/path_tracker.h"

#include <algorithm>
#include <limits>
#include <string>

#include "spira/base/error.h"

namespace spira {

namespace {

constexpr double kReachPositionTol = 1e-6;     // mm
constexpr double kReachOrientationTol = 1e-8;  // rad
constexpr size_t kProgressStride = 4096;

}  // namespace

PathTrack trackPath(const ArmIk& ik, const std::vector<Transform>& baseTcp, const Transform& flangeTcp,
                    const JointVector& seed, const std::optional<ArmConfiguration>& configuration,
                    Progress& progress)
{
  PathTrack track;
  track.configuration = configuration ? *configuration : ik.configurationOf(seed);
  track.poses.resize(baseTcp.size());
  track.minLimitMargin = baseTcp.empty() ? 0.0 : std::numeric_limits<double>::infinity();
  if (!flangeTcp.matrix().allFinite() || !seed.allFinite())
    throw InputError("the tool frame or the seed joints of the path hold NaN or infinity",
                     "check the cell's tool (TCP) and start pose");
  const Transform tcpFlange = flangeTcp.inverse();
  JointVector previous = seed;
  for (size_t i = 0; i < baseTcp.size(); ++i) {
    if (i % kProgressStride == 0) {
      progress.checkCancel();
      progress.report(static_cast<double>(i) / static_cast<double>(baseTcp.size()), "inverse kinematics");
    }
    // Named by index here: ArmIk::solve would refuse it too, but could not say which pose it was.
    if (!baseTcp[i].matrix().allFinite())
      throw InputError("path pose " + std::to_string(i) + " holds NaN or infinity",
                       "check point " + std::to_string(i) + " of the trajectory (position and frame)");
    TrackedPose& pose = track.poses[i];
    const std::optional<IkSolution> s = ik.solve(baseTcp[i] * tcpFlange, track.configuration, previous);
    pose.reachable = s && s->positionError < kReachPositionTol && s->orientationError < kReachOrientationTol;
    pose.q = pose.reachable ? s->q : previous;
    pose.limitMargin = pose.reachable ? s->limitMargin : ik.limitMargin(pose.q);
    pose.dexterity = pose.reachable ? s->dexterity : 0.0;
    pose.jointStep = (pose.q - previous).cwiseAbs().maxCoeff();
    previous = pose.q;

    track.unreachable += pose.reachable ? 0 : 1;
    track.outsideLimits += pose.limitMargin < 0.0 ? 1 : 0;
    track.minDexterity = std::min(track.minDexterity, pose.dexterity);
    track.minLimitMargin = std::min(track.minLimitMargin, pose.limitMargin);
    track.maxJointStep = std::max(track.maxJointStep, pose.jointStep);
  }
  progress.report(1.0, "inverse kinematics");
  return track;
}

}  // namespace spira
