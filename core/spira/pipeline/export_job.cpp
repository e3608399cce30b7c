#include "spira/pipeline/export_job.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/export/export_path.h"
#include "spira/path/dwell.h"
#include "spira/pipeline/plan_motion.h"
#include "spira/pipeline/sub_paths.h"
#include "spira/prep/actuator_lead.h"
#include "spira/prep/channels.h"

namespace spira {
namespace {

constexpr double kSamePlace = 0.5;  // mm: a travel point this close to the previous one is left out

void mergeReport(PrepReport& total, const PrepReport& part, bool first)
{
  total.pointsIn += part.pointsIn;
  total.samples += part.samples;
  total.pointsOut += part.pointsOut;
  total.maxChordDeviation = std::max(total.maxChordDeviation, part.maxChordDeviation);
  total.maxSmoothingOffset = std::max(total.maxSmoothingOffset, part.maxSmoothingOffset);
  total.maxOrientationDeviation = std::max(total.maxOrientationDeviation, part.maxOrientationDeviation);
  for (const auto& [name, value] : part.maxChannelDeviation)
    total.maxChannelDeviation[name] = std::max(total.maxChannelDeviation[name], value);
  total.minSegment = first ? part.minSegment : std::min(total.minSegment, part.minSegment);
  total.maxSegment = std::max(total.maxSegment, part.maxSegment);
  total.spacingOverrides += part.spacingOverrides;
}

TrajectoryPoint travelPoint(const TrajectoryPoint& beside, const Vec3& position, double speed)
{
  TrajectoryPoint p = beside;
  p.position = position;
  p.arcOn = false;
  p.travelSpeed = speed;
  p.wireFeed = 0.0;
  return p;
}

// Retract from `from` along the torch axis, rise to zSafe, travel, come down above `to` and
// approach it along its torch axis; the arc is off throughout. The retract side keeps the path
// index of `from`, the approach side that of `to`, so each is solved with its own sub-path.
Trajectory travelBetween(const TrajectoryPoint& from, const TrajectoryPoint& to, double zSafe,
                         const PrepParams& prep)
{
  Trajectory t;
  const auto add = [&t, &prep](const TrajectoryPoint& beside, const Vec3& position) {
    if (!t.points.empty() && (t.points.back().position - position).norm() < kSamePlace) return;
    t.points.push_back(travelPoint(beside, position, prep.travelSpeed));
  };
  const Vec3 retract = from.position + prep.travelClearance * from.build;
  const Vec3 approach = to.position + prep.travelClearance * to.build;
  add(from, retract);
  add(from, Vec3(retract.x(), retract.y(), std::max(zSafe, retract.z())));
  add(to, Vec3(approach.x(), approach.y(), std::max(zSafe, approach.z())));
  add(to, approach);
  return t;
}

// The lifted pose of a dwell at `at`: travelBetween from a point to itself, with no safe height to
// rise to, is the retract along the torch axis alone. It carries the wait in the dwell channel.
Trajectory dwellLift(const TrajectoryPoint& at, double seconds, const PrepParams& prep)
{
  Trajectory lift = travelBetween(at, at, -std::numeric_limits<double>::infinity(), prep);
  lift.extra[kDwellChannel] = {seconds};
  return lift;
}

// The pieces of one sub-path that are prepared on their own: a dwell inside it ends one piece at
// its point and starts the next there, so no smoothing or decimation runs across the lift (nor
// drops or moves the point the torch leaves and comes back to). Dwells at the sub-path's ends need
// no cut: the torch is lifted there anyway, on the travel before or after.
std::vector<SubPathRange> dwellPieces(const Trajectory& planned, const SubPathRange& range)
{
  std::vector<SubPathRange> pieces{range};
  for (size_t i = range.begin + 1; i + 1 < range.end; ++i) {
    if (dwellAt(planned, i) <= 0.0) continue;
    pieces.back().end = i + 1;
    pieces.push_back({range.path, i, range.end});
  }
  return pieces;
}

// Puts a wait on the travel point `k` (the retract or the approach of travelBetween).
void addWait(Trajectory& travel, size_t k, double seconds)
{
  if (seconds <= 0.0) return;
  std::vector<double>& dwell = travel.extra[kDwellChannel];
  dwell.resize(travel.size(), 0.0);
  dwell[k] += seconds;
}

// The wire-feed setpoints led by the feeder's lag, per stretch of arc: the channels
// kWfsCommandChannel (setpoint due at each point) and kWfsLeadChannel (how long before reaching
// the point it must be written) that the exporters read.
void leadWireFeed(Trajectory& program, const LagModel& lag)
{
  const size_t n = program.size();
  std::vector<double> command(n), lead(n, 0.0);
  for (size_t i = 0; i < n; ++i) command[i] = program.points[i].wireFeed;
  size_t i = 0;
  while (i < n) {
    if (!program.points[i].arcOn) {
      ++i;
      continue;
    }
    SubPathRange span{program.points[i].path, i, i};
    while (span.end < n && program.points[span.end].arcOn && program.points[span.end].path == span.path)
      ++span.end;
    const Trajectory piece = subTrajectory(program, span);
    const LeadResult led = leadChannel(piece, kWireFeedChannel, lag);
    for (size_t k = 0; k < piece.size(); ++k) {
      command[span.begin + k] = led.command[k];
      lead[span.begin + k] = led.time[k] - led.triggerTime[k];
    }
    i = span.end;
  }
  program.extra[kWfsCommandChannel] = std::move(command);
  program.extra[kWfsLeadChannel] = std::move(lead);
}

}  // namespace

ExportOutcome exportTrajectory(const PluginRegistry& registry, const Trajectory& planned,
                               const ExportJob& job, const std::filesystem::path& outDir, Progress& progress)
{
  const auto t0 = std::chrono::steady_clock::now();
  const ExporterPlugin& exporter = registry.exporter(job.exporterId);
  const ParamSet params = job.exporterParams.withDefaults(exporter.schema());
  exporter.schema().validate(params);
  if (planned.empty()) throw InputError("the plan has no points", "plan the part before exporting");
  const RobotCell* cell = exporter.usesRobotCell() ? job.cell : nullptr;

  ExportOutcome out;
  // Sub-paths (a multi-branch plan) are prepared one by one, so no smoothing or decimation runs
  // across the gap between them, then laid out with travel moves in between.
  const std::vector<SubPathRange> ranges = subPathRanges(planned);
  out.subPaths = ranges.size();
  out.dwells = dwellTotals(planned).count;
  double zTop = planned.points.front().position.z();
  for (const TrajectoryPoint& p : planned.points) zTop = std::max(zTop, p.position.z());
  const double zSafe = zTop + job.prep.travelClearance;
  if (!job.plannedCollision.empty() && job.plannedCollision.size() != planned.size())
    throw InputError("the plan's collision flags do not match its points", "plan the part again");
  Trajectory program;
  std::vector<bool> colliding;  // per program point: it stands for a colliding planned point
  const double total = static_cast<double>(planned.size());
  // A dwell's wait at the last point of a sub-path, due on the retract that follows it.
  double pendingWait = 0.0;
  bool first = true;
  for (size_t r = 0; r < ranges.size(); ++r) {
    const std::vector<SubPathRange> pieces = dwellPieces(planned, ranges[r]);
    for (size_t q = 0; q < pieces.size(); ++q) {
      const SubPathRange& piece = pieces[q];
      SubProgress prepProgress(progress, 0.4 * static_cast<double>(piece.begin) / total,
                               0.4 * static_cast<double>(piece.end) / total, "path preparation");
      Trajectory source = subTrajectory(planned, piece);
      source.extra.erase(kDwellChannel);  // the waits are laid out as lifts, never smoothed
      const PreparedTrajectory prepared = prepareTrajectory(source, job.prep, prepProgress);
      if (!prepared.trajectory.empty()) {
        const TrajectoryPoint& start = prepared.trajectory.points.front();
        const double startWait = q == 0 ? dwellAt(planned, piece.begin) : 0.0;
        if (q > 0) {
          appendTrajectory(program,
                           dwellLift(program.points.back(), dwellAt(planned, piece.begin), job.prep));
        } else if (!program.empty()) {
          Trajectory travel = travelBetween(program.points.back(), start, zSafe, job.prep);
          addWait(travel, 0, pendingWait);
          addWait(travel, travel.size() - 1, startWait);
          appendTrajectory(program, travel);
        } else if (startWait > 0.0) {
          appendTrajectory(program, dwellLift(start, startWait, job.prep));
        }
      }
      colliding.resize(program.size(), false);
      for (double at : prepared.sourceParam) {
        // A target between two planned points collides when either does.
        const size_t lo = piece.begin + static_cast<size_t>(std::floor(at));
        const size_t hi = std::min(piece.begin + static_cast<size_t>(std::ceil(at)), piece.end - 1);
        colliding.push_back(!job.plannedCollision.empty() &&
                            (job.plannedCollision[lo] || job.plannedCollision[hi]));
      }
      appendTrajectory(program, prepared.trajectory);
      mergeReport(out.prep, prepared.report, first);
      first = false;
    }
    pendingWait = ranges[r].size() > 1 ? dwellAt(planned, ranges[r].end - 1) : 0.0;
  }
  if (pendingWait > 0.0 && !program.empty()) {
    appendTrajectory(program, dwellLift(program.points.back(), pendingWait, job.prep));
    colliding.resize(program.size(), false);
  }
  if (job.prep.leadWireFeed) leadWireFeed(program, job.prep.wireFeedLag);
  out.robotTargets = program.size();

  JointTrajectory joints;
  if (cell) {
    SubProgress ikProgress(progress, 0.4, 0.7, "robot targets");
    // The prepared points are solved (and their spin optimised) afresh: fewer points than the plan,
    // so the program's joints are exactly those of its own targets; one solve per sub-path.
    MotionSettings ms;
    ms.optimiseSpin = job.optimiseSpin;
    if (job.positionerToleranceDeg)
      ms.process.positionerTiltTolerance = degToRad(*job.positionerToleranceDeg);
    joints = solveSubPaths(*cell, program, motionParamsFor(*cell, ms), ikProgress).joints;
    for (size_t i = 0; i < joints.points.size(); ++i) {
      out.unreachableTargets += !joints.points[i].reachable;
      if (colliding[i]) joints.points[i].collision = true;
    }
  }
  SubProgress writeProgress(progress, 0.7, 1.0, "writing the program");
  const ExportInput input{program, cell ? &joints : nullptr, job.header};
  out.result = exporter.write(input, params, outDir, writeProgress);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace spira
