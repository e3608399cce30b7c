#include "spira/planning/branch_plan.h"

#include <algorithm>

#include "spira/base/error.h"
#include "spira/path/too_short_error.h"
#include "spira/planning/branch_refusal.h"

namespace spira {

namespace {

void addCriterion(LengthCriterion& total, const LengthCriterion& part, bool first)
{
  if (first) {
    total = part;
    return;
  }
  total.lengthMin = std::min(total.lengthMin, part.lengthMin);
  total.lengthMax = std::max(total.lengthMax, part.lengthMax);
  total.nLayers = std::min(total.nLayers, part.nLayers);
  total.stepSpread = std::max(total.stepSpread, part.stepSpread);
  total.window = std::min(total.window, part.window);
  total.ok = total.ok && part.ok;
}

std::string role(const BranchPiece& p, size_t index)
{
  return "sub-part " + std::to_string(index) + (p.trunk ? " (trunk)" : " (branch)");
}

}  // namespace

PathSummary wholePathSummary(const PlanOutput& plan)
{
  PathSummary s;
  s.partClass = plan.topology.partClass;
  s.pointCount = plan.spiral.trajectory.size();
  s.fieldKind = plan.fieldKind;
  s.hasClosure = plan.hasClosure;
  s.closure = plan.closure;
  s.generatrices = plan.generatrices.lines.size();
  s.spiral = plan.spiral.report;
  s.process = plan.process;
  s.warnings = plan.warnings;
  return s;
}

void addSpiralReport(SpiralReport& total, const SpiralReport& part, size_t offset, bool first)
{
  const double pointsBefore = static_cast<double>(total.nPoints);
  if (first) {
    total = part;
    total.violations.clear();
  } else {
    total.nStartupRevolutions += part.nStartupRevolutions;
    total.nLayers += part.nLayers;
    total.nEndRevolutions += part.nEndRevolutions;
    total.nRevolutions += part.nRevolutions;
    total.collapsedRevolutions += part.collapsedRevolutions;
    total.nPoints += part.nPoints;
    total.generatrixLengthMin = std::min(total.generatrixLengthMin, part.generatrixLengthMin);
    total.generatrixLengthMax = std::max(total.generatrixLengthMax, part.generatrixLengthMax);
    total.modulatedLengthMin = std::min(total.modulatedLengthMin, part.modulatedLengthMin);
    total.modulatedLengthMax = std::max(total.modulatedLengthMax, part.modulatedLengthMax);
    total.stepMin = std::min(total.stepMin, part.stepMin);
    total.stepMax = std::max(total.stepMax, part.stepMax);
    total.seamStep = std::max(total.seamStep, part.seamStep);
    total.heightMin = std::min(total.heightMin, part.heightMin);
    total.heightMax = std::max(total.heightMax, part.heightMax);
    if (part.rampHeightMax > 0.0) {
      const bool noRampYet = total.rampHeightMax <= 0.0;
      total.rampHeightMin =
          noRampYet ? part.rampHeightMin : std::min(total.rampHeightMin, part.rampHeightMin);
      total.rampHeightMax = std::max(total.rampHeightMax, part.rampHeightMax);
    }
    const double n = static_cast<double>(part.nPoints);
    if (pointsBefore + n > 0)
      total.heightMean = (total.heightMean * pointsBefore + part.heightMean * n) / (pointsBefore + n);
    total.pathLength += part.pathLength;
    total.maxJump = std::max(total.maxJump, part.maxJump);
    total.seamRiseMax = std::max(total.seamRiseMax, part.seamRiseMax);
    addCriterion(total.lengthCriterion, part.lengthCriterion, false);
    addCriterion(total.thesisLengthCriterion, part.thesisLengthCriterion, false);
    total.feasible = total.feasible && part.feasible;
    total.heightTolerance = std::max(total.heightTolerance, part.heightTolerance);
    total.modulatedViolations += part.modulatedViolations;
    total.closureGap = std::max(total.closureGap, part.closureGap);
    total.normalsEstimated = total.normalsEstimated || part.normalsEstimated;
    total.normalsFlipped = total.normalsFlipped || part.normalsFlipped;
  }
  for (HeightViolation v : part.violations) {
    v.point += offset;
    total.violations.push_back(v);
  }
}

void addProcessReport(ProcessReport& total, const ProcessReport& part, size_t offset, bool first)
{
  if (first) {
    total = part;
    total.violations.clear();
  } else {
    total.buildTime += part.buildTime;
    total.dwells += part.dwells;
    total.dwellTime += part.dwellTime;
    total.wireLength += part.wireLength;
    total.depositVolume += part.depositVolume;
    total.travelSpeedMin = std::min(total.travelSpeedMin, part.travelSpeedMin);
    total.travelSpeedMax = std::max(total.travelSpeedMax, part.travelSpeedMax);
    total.wireFeedMin = std::min(total.wireFeedMin, part.wireFeedMin);
    total.wireFeedMax = std::max(total.wireFeedMax, part.wireFeedMax);
    total.withinLimits = total.withinLimits && part.withinLimits;
  }
  for (ProcessViolation v : part.violations) {
    v.point += offset;
    total.violations.push_back(v);
  }
}

void planBranchPieces(const PluginRegistry& registry, const PlanRequest& whole, BranchDecomposition pieces,
                      PlanOutput& out, Progress& progress)
{
  out.fieldKind = "geodesic_distance";
  out.field = std::move(pieces.field);
  out.hasClosure = false;
  out.generatrices = Generatrices();
  out.spiral = SpiralResult();
  out.process = ProcessReport();
  out.paths.clear();
  BranchingSummary branching;
  branching.saddles = pieces.saddles;
  branching.junctionGap = pieces.junctionGap;
  branching.junctionGapArea = pieces.gapArea;
  branching.depthLimited = pieces.depthLimited;
  if (pieces.depthLimited)
    out.warnings.push_back("the part branches more than " + std::to_string(pieces.saddles.size()) +
                           " times deep; the deepest sub-parts were left whole");

  bool allNormals = true;
  const size_t count = pieces.pieces.size();
  for (size_t k = 0; k < count; ++k) {
    const BranchPiece& piece = pieces.pieces[k];
    const size_t freeEdges = piece.report.boundaryLoops.size();
    if (freeEdges > 2) refuseUnsplitBranch(role(piece, k), freeEdges, pieces.minPerimeter);
    PlanRequest sub(piece.mesh, piece.report, whole);
    sub.lowerLoopOverride = piece.lowerLoop;
    sub.baseSupportGap = piece.supportGap;
    SubProgress p(progress, static_cast<double>(k) / count, static_cast<double>(k + 1) / count,
                  role(piece, k));
    PlanOutput plan;
    try {
      plan = planMonoBranch(registry, sub, p);
    } catch (const TooShortError& e) {
      throw TooShortError(role(piece, k) + " of the multi-branch part: " + e.what(), e.hint(), e.length(),
                          e.needed());
    } catch (const InputError& e) {
      throw InputError(role(piece, k) + " of the multi-branch part: " + e.what(), e.hint());
    } catch (const AlgorithmError& e) {
      throw AlgorithmError(role(piece, k) + " of the multi-branch part: " + e.what(), e.hint());
    }

    const size_t offset = out.spiral.trajectory.size();
    PathSummary s = wholePathSummary(plan);
    s.path = static_cast<int>(k);
    s.parent = piece.parent;
    s.depth = piece.depth;
    s.trunk = piece.trunk;
    s.baseLevel = piece.lowerLevel;
    s.area = piece.area;
    s.firstPoint = offset;
    Trajectory& path = out.spiral.trajectory;
    for (TrajectoryPoint pt : plan.spiral.trajectory.points) {
      pt.path = static_cast<int>(k);
      path.points.push_back(pt);
    }
    // Extra channels of one sub-path read 0 on the others.
    for (auto& [key, values] : plan.spiral.trajectory.extra) {
      std::vector<double>& channel = path.extra[key];
      channel.resize(offset, 0.0);
      channel.insert(channel.end(), values.begin(), values.end());
    }
    for (auto& [key, values] : path.extra) values.resize(path.size(), 0.0);
    addSpiralReport(out.spiral.report, plan.spiral.report, offset, k == 0);
    addProcessReport(out.process, plan.process, offset, k == 0);
    for (const auto& w : plan.warnings) out.warnings.push_back("path " + std::to_string(k) + ": " + w);
    allNormals = allNormals && plan.generatrices.normals.size() == plan.generatrices.lines.size();
    for (auto& line : plan.generatrices.lines) out.generatrices.lines.push_back(std::move(line));
    for (auto& normals : plan.generatrices.normals) out.generatrices.normals.push_back(std::move(normals));
    out.paths.push_back(std::move(s));
  }
  if (!allNormals) out.generatrices.normals.clear();
  out.branching = std::move(branching);
}

}  // namespace spira
