#include "spira/pipeline/plan_records.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "spira/document/stage_report_codec.h"
#include "spira/plugin/strategy_name.h"

namespace spira {
namespace {

constexpr double kMmPerSecondToMetresPerMinute = 60.0 / 1000.0;
constexpr size_t kListed = 1000;  // flagged and violating points a report lists

const char* partTypeName(PartClass c)
{
  return c == PartClass::Open ? "open" : "closed";
}

SecondsPerStep secondsOf(const StageTimings& timings, bool withTotal)
{
  SecondsPerStep out;
  double total = 0.0;
  for (const auto& [stage, seconds] : timings) {
    out[stage] = seconds;
    total += seconds;
  }
  if (withTotal) out["total"] = total;
  return out;
}

PathRecord pathRecord(const PathSummary& p)
{
  const SpiralReport& s = p.spiral;
  PathRecord r;
  r.path = p.path;
  r.parent = p.parent;
  r.depth = p.depth;
  r.role = p.trunk ? "trunk" : "branch";
  r.partType = partTypeName(p.partClass);
  r.baseLevel = p.baseLevel;
  r.area = p.area;
  r.firstPoint = static_cast<std::int64_t>(p.firstPoint);
  r.points = static_cast<std::int64_t>(p.pointCount);
  r.generatrices = static_cast<std::int64_t>(p.generatrices);
  r.generatrixLengthMin = s.generatrixLengthMin;
  r.generatrixLengthMax = s.generatrixLengthMax;
  r.revolutions = s.nRevolutions;
  r.heightMin = s.heightMin;
  r.heightMax = s.heightMax;
  r.heightMean = s.heightMean;
  r.feasible = p.feasible();
  r.depositFlags = static_cast<std::int64_t>(p.depositFlags);
  r.violations = static_cast<std::int64_t>(s.violations.size());
  r.pathLength = s.pathLength;
  r.maxJump = s.maxJump;
  r.buildTime = p.process.buildTime;
  if (p.hasClosure) r.closurePoint = p.closure.point;
  return r;
}

BranchingRecord branchingRecord(const BranchingSummary& b)
{
  BranchingRecord r;
  for (const BranchSaddle& s : b.saddles) {
    SaddleRecord saddle;
    saddle.belowPath = s.piece;
    saddle.level = s.level;
    saddle.position = s.position;
    saddle.branches = static_cast<std::int64_t>(s.branches);
    saddle.trunkTopLevel = s.trunkTop;
    saddle.branchBaseLevel = s.branchBase;
    saddle.gapArea = s.gapArea;
    saddle.bisections = s.bisections;
    r.saddles.push_back(saddle);
  }
  r.junctionGap = b.junctionGap;
  r.junctionGapArea = b.junctionGapArea;
  r.depthLimited = b.depthLimited;
  return r;
}

SolidRecord solidRecord(const SolidWall& wall)
{
  SolidRecord r;
  r.wallThickness = {wall.thickness.median, wall.thickness.thinnest, wall.thickness.thickest};
  r.wallAreaFraction = wall.wallAreaFraction;
  r.beadWidth = wall.beadWidth;
  r.solidFaces = static_cast<std::int64_t>(wall.solidFaces);
  r.midSurfaceFaces = wall.midSurface ? static_cast<std::int64_t>(wall.midSurface->faceCount()) : 0;
  r.warnings = wall.warnings;
  return r;
}

}  // namespace

DepositCheckRecord depositCheckRecord(const DepositCheckReport& d)
{
  DepositCheckRecord r;
  r.feasible = d.feasible;
  r.summary = d.summary();
  r.pointsChecked = static_cast<std::int64_t>(d.pointsChecked);
  r.heightMin = d.heightMin;
  r.heightMax = d.heightMax;
  r.heightMean = d.heightMean;
  r.plannedDifferenceMax = d.plannedDifferenceMax;
  r.jumpLength = d.jumpLength;
  for (int k = 0; k < 5; ++k)
    r.counts[depositDefectName(static_cast<DepositDefect>(k))] = static_cast<std::int64_t>(d.counts[k]);
  r.flagged = static_cast<std::int64_t>(d.flags.size());
  for (size_t i = 0; i < d.flags.size() && i < kListed; ++i) {
    const DepositFlag& f = d.flags[i];
    r.flaggedPoints.push_back(
        {static_cast<std::int64_t>(f.point), depositDefectName(f.kind), f.height, f.position});
  }
  if (d.coverageChecked)
    r.coverage = CoverageRecord{d.surfaceArea, d.uncoveredArea, d.uncoveredFraction(),
                                d.coverRadius, d.largestGap,    d.largestGapAt};
  return r;
}

FieldStageReport fieldStageReport(const PlanOutput& plan)
{
  FieldStageReport r;
  r.kind = plan.fieldKind;
  r.timings = secondsOf(plan.timings, false);
  if (plan.hasClosure) {
    r.closurePoint = plan.closure.point;
    r.closureDistance = plan.closure.distance;
  }
  return r;
}

GeneratricesStageReport generatricesStageReport(const PlanOutput& plan)
{
  const SpiralReport& s = plan.spiral.report;
  return {static_cast<std::int64_t>(plan.generatrices.lines.size()), s.generatrixLengthMin,
          s.generatrixLengthMax};
}

SpiralStageReport spiralStageReport(const PlanOutput& plan, const std::string& strategy)
{
  const SpiralReport& s = plan.spiral.report;
  SpiralStageReport r;
  r.partType = plan.branching ? "multi_branch" : partTypeName(plan.topology.partClass);
  r.strategy = strategyName(strategy);
  r.field = plan.fieldKind;
  r.generatrices = static_cast<std::int64_t>(plan.generatrices.lines.size());
  r.generatrixLengthMin = s.generatrixLengthMin;
  r.generatrixLengthMax = s.generatrixLengthMax;
  r.startupRevolutions = s.nStartupRevolutions;
  r.layers = s.nLayers;
  r.endRevolutions = s.nEndRevolutions;
  r.revolutions = s.nRevolutions;
  r.points = static_cast<std::int64_t>(s.nPoints);
  r.stepMin = s.stepMin;
  r.stepMax = s.stepMax;
  r.heightMin = s.heightMin;
  r.heightMax = s.heightMax;
  r.heightMean = s.heightMean;
  r.rampHeightMin = s.rampHeightMin;
  r.rampHeightMax = s.rampHeightMax;
  r.h = s.h;
  r.hMin = s.hMin;
  r.hMax = s.hMax;
  r.heightTolerance = s.heightTolerance;
  r.collapsedRevolutions = s.collapsedRevolutions;
  r.feasible = plan.feasible();
  r.windowFeasible = s.feasible;
  r.depositCheck = depositCheckRecord(plan.deposits);
  if (plan.solid) r.solid = solidRecord(*plan.solid);
  const LengthCriterion& c = s.lengthCriterion;
  r.lengthCriterion = {c.lengthMin, c.lengthMax, c.stepSpread, c.window, c.nLayers, c.ok};
  r.violations = static_cast<std::int64_t>(s.violations.size());
  r.modulatedViolations = static_cast<std::int64_t>(s.modulatedViolations);
  r.closureGap = s.closureGap;
  for (size_t i = 0; i < s.violations.size() && i < kListed; ++i) {
    const HeightViolation& v = s.violations[i];
    r.violationPoints.push_back({static_cast<std::int64_t>(v.point), v.revolution, v.generatrix, v.height,
                                 spiralPhaseName(v.phase), v.aboveWindow});
  }
  if (plan.hasClosure) {
    r.closurePoint = plan.closure.point;
    r.closureDistance = plan.closure.distance;
  }
  r.pathLength = s.pathLength;
  r.maxJump = s.maxJump;
  r.seamRiseMax = s.seamRiseMax;
  r.buildTime = plan.process.buildTime;
  if (plan.process.dwells > 0) {
    r.dwells = static_cast<std::int64_t>(plan.process.dwells);
    r.dwellTime = plan.process.dwellTime;
  }
  if (plan.layers) {
    const LayerStats& l = *plan.layers;
    r.layers = l.layers;
    r.deltaMin = l.deltaMin;
    r.deltaMax = l.deltaMax;
    r.maxKinkDeg = l.maxKinkDeg;
    r.layerKinksDeg = l.kinkDeg;
    r.arcStarts = l.arcStarts;
    r.layerOutput = l.output;
    r.layerEnd = l.end;
  }
  r.timings = secondsOf(plan.timings, true);
  r.warnings = plan.warnings;
  r.pathCount = plan.paths.empty() ? 1 : static_cast<std::int64_t>(plan.paths.size());
  for (const PathSummary& p : plan.paths) r.paths.push_back(pathRecord(p));
  if (plan.branching) r.branching = branchingRecord(*plan.branching);
  return r;
}

ProcessStageReport processStageReport(const ProcessReport& p)
{
  ProcessStageReport r;
  r.withinLimits = p.withinLimits;
  r.travelSpeedMin = p.travelSpeedMin;
  r.travelSpeedMax = p.travelSpeedMax;
  r.wireFeedMin = p.wireFeedMin * kMmPerSecondToMetresPerMinute;
  r.wireFeedMax = p.wireFeedMax * kMmPerSecondToMetresPerMinute;
  r.wireLength = p.wireLength;
  r.depositVolume = p.depositVolume;
  r.limitViolations = static_cast<std::int64_t>(p.violations.size());
  return r;
}

nlohmann::json planReportJson(const PlanOutput& plan, const std::string& strategy)
{
  nlohmann::json j = reportToJson(spiralStageReport(plan, strategy));
  j["process"] = reportToJson(processStageReport(plan.process));
  return j;
}

}  // namespace spira
