#include "spira/pipeline/thermal_stage.h"

#include <algorithm>

#include "spira/base/progress.h"
#include "spira/thermal/thermal_replan.h"
#include "spira/thermal/thermal_substrate.h"

namespace spira {

namespace {

double maxOf(const std::vector<double>& v)
{
  return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
}

}  // namespace

ThermalStudySettings thermalStudySettingsFor(const Trajectory& path, const ThermalStageSettings& settings,
                                             double beadWidth)
{
  ThermalStudySettings s = settings.study;
  s.mesh.thickness = beadWidth;
  s.solver.sourceRadius = settings.arcRadius > 0.0 ? settings.arcRadius : 0.5 * beadWidth;
  s.mesh.substrateZ = path.empty() ? 0.0 : substratePlaneOf(path);
  return s;
}

ThermalStageResult thermalStageResultOf(const ThermalStudy& study)
{
  const ThermalMesh& mesh = study.mesh;
  const ThermalResult& r = study.result;
  ThermalStageResult out;
  out.nodes = mesh.nodes;
  out.triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) out.triangles.push_back({t[0], t[1], t[2]});
  out.pointNode.reserve(mesh.pointHeatIndex.size());
  for (int h : mesh.pointHeatIndex) out.pointNode.push_back(mesh.heatNode[static_cast<size_t>(h)]);
  out.peak = r.peak;
  out.interpass = r.interpass;
  out.timeAboveMelt = r.timeAboveMelt;
  out.poolLength = study.poolLength;
  out.bond = study.bond;
  out.risk.assign(study.risk.begin(), study.risk.end());
  out.nodePeak = r.nodePeak;
  out.probeNodes.assign(r.probeNodes.begin(), r.probeNodes.end());
  out.probeTimes = r.probeTimes;
  out.probeTemperatures = r.probeTemperatures;
  out.frames = ThermalFrameSet::quantise(study.frames.times, study.frames.values);
  return out;
}

ThermalStageReport thermalStageReportOf(const ThermalStudy& study, const ThermalStudySettings& settings,
                                        double interpassLimit)
{
  const ThermalResult& r = study.result;
  ThermalStageReport rep;
  rep.material = settings.solver.material.name;
  rep.meltingTemperature = settings.solver.material.meltingTemperature;
  rep.power = settings.solver.power;
  rep.interpassLimit = interpassLimit;
  rep.maxPeak = maxOf(r.peak);
  rep.maxInterpass = maxOf(r.interpass);
  rep.maxPoolLength = maxOf(study.poolLength);
  rep.maxBond = maxOf(study.bond);
  rep.bondThreshold = settings.bondThreshold;
  rep.riskPoints = study.riskPoints;
  if (interpassLimit > 0.0)
    rep.pointsOverLimit =
        std::count_if(r.interpass.begin(), r.interpass.end(), [&](double t) { return t > interpassLimit; });
  rep.energyIn = r.energy.in;
  rep.energyStored = r.energy.stored;
  rep.energyLost = r.energy.lost;
  rep.nodes = r.nodes;
  rep.elements = r.elements;
  rep.steps = r.steps;
  rep.simulatedTime = r.simulatedTime;
  rep.timings = {{"mesh", study.meshSeconds}, {"simulation", r.seconds}, {"solver", r.solverSeconds}};
  return rep;
}

ThermalStageOutput runThermalStage(const Trajectory& path, const ThermalStageSettings& settings,
                                   const ProcessSettings& process, Progress& progress)
{
  ThermalStudySettings study = thermalStudySettingsFor(path, settings, process.beadWidth);
  ThermalStageOutput out;
  if (!(settings.interpassLimit > 0.0) ||
      !(settings.remedyDeposit || settings.remedyHeat || settings.remedyDwell)) {
    const ThermalStudy s = runThermalStudy(path, study, progress);
    out.result = std::make_shared<const ThermalStageResult>(thermalStageResultOf(s));
    out.report =
        std::make_shared<const ThermalStageReport>(thermalStageReportOf(s, study, settings.interpassLimit));
    return out;
  }
  study.solver.powerPerWireFeed = powerPerWireFeedOf(path, study.solver.power);
  ThermalReplanSettings replan;
  replan.interpassMax = settings.interpassLimit;
  replan.limits = process.limits;
  replan.deposit = settings.remedyDeposit;
  replan.heat = settings.remedyHeat;
  replan.dwell = settings.remedyDwell;
  replan.maxDwell = settings.maxDwell;
  replan.hMin = settings.windowMin;
  const ThermalReplanOutcome o = replanForInterpass(path, study, replan, progress);
  ThermalStageResult result = thermalStageResultOf(o.study);
  if (!(o.trajectory == path)) result.replanned = std::make_shared<const Trajectory>(o.trajectory);
  ThermalStageReport report = thermalStageReportOf(o.study, study, settings.interpassLimit);
  report.limitMet = o.limitMet;
  report.revolutionsAdded = o.revolutionsAdded;
  report.buildTimeAdded = o.buildTimeAdded;
  report.remediesApplied = o.applied;
  report.dwells = o.dwells;
  report.dwellTime = o.dwellTime;
  if (!o.why.empty()) report.whyNotMet = o.why;
  out.result = std::make_shared<const ThermalStageResult>(std::move(result));
  out.report = std::make_shared<const ThermalStageReport>(std::move(report));
  return out;
}

}  // namespace spira
