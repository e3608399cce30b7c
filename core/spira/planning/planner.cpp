#include "spira/planning/planner.h"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <sstream>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/contour/branch_levels.h"
#include "spira/field/harmonic_field.h"
#include "spira/field/heat_distance.h"
#include "spira/path/spiral_builder.h"
#include "spira/planning/branch_plan.h"
#include "spira/planning/branch_refusal.h"
#include "spira/planning/plan_schemas.h"
#include "spira/planning/stage_clock.h"
#include "spira/planning/substrate_contact.h"

namespace spira {
namespace {

ParamSet paramsFor(const PlanRequest& r, const std::string& section)
{
  auto it = r.params.find(section);
  return it == r.params.end() ? ParamSet() : it->second;
}

struct Settings {
  SpiralSettings spiral;
  ProcessSettings process;
  const DecomposerPlugin* decomposer = nullptr;
  ParamSet decomposerParams;
};

// Settings first: a contradictory window is reported before any computation.
Settings settingsFor(const PluginRegistry& registry, const PlanRequest& request)
{
  Settings s;
  PlanSections sections = readPlanSections(request.params);
  s.spiral = sections.spiral;
  s.process = std::move(sections.process);
  s.decomposer = &registry.decomposer(request.decomposerId);
  s.decomposerParams = paramsFor(request, request.decomposerId).withDefaults(s.decomposer->schema());
  s.decomposer->schema().validate(s.decomposerParams);
  return s;
}

// An open part ends on its upper free edge, so the last revolutions follow it: an edge shorter than
// one bead ring makes them pile onto themselves (a degenerate, needle-like top).
void checkUpperEdge(const PartTopology& topology, const Settings& settings)
{
  if (!topology.upper || topology.upper->length >= settings.spiral.minRevolutionLength) return;
  std::ostringstream what;
  what << std::fixed << std::setprecision(2) << "the part's upper free edge is only "
       << topology.upper->length << " mm around, shorter than one bead ring ("
       << settings.spiral.minRevolutionLength << " mm): the last revolutions would pile onto themselves";
  throw InputError(
      what.str(),
      "cut the part below its narrow top, close the top (a closed part ends at a closure point), "
      "or lower the spiral's 'Smallest closing ring'");
}

void computeField(const PlanRequest& request, PlanOutput& out, Progress& progress)
{
  SubProgress p(
      progress, 0.0, 0.3,
      out.topology.partClass == PartClass::Open ? "harmonic field" : "geodesic distance from the base");
  if (out.topology.partClass == PartClass::Open) {
    out.fieldKind = "harmonic";
    out.field = harmonicField(request.mesh, out.topology.lower.vertices, out.topology.upper->vertices, p);
  } else {
    out.fieldKind = "geodesic_distance";
    out.field = heatGeodesicDistance(request.mesh, out.topology.lower.vertices, HeatDistanceOptions{}, p);
  }
}

// A part standing on material `gap` below its lower edge: each generatrix starts that much lower,
// straight on from its first segment, so the spiral's first ring is laid h_min .. h_max above the
// material, not above the edge. No point lands on the extension as long as gap < h_min.
void extendBelowBase(Generatrices& g, double gap)
{
  for (size_t k = 0; k < g.lines.size(); ++k) {
    Polyline& line = g.lines[k];
    if (line.size() < 2) continue;
    const Vec3 down = (line[0] - line[1]).normalized();
    line.insert(line.begin(), line[0] + gap * down);
    if (k < g.normals.size() && !g.normals[k].empty())
      g.normals[k].insert(g.normals[k].begin(), g.normals[k][0]);
  }
}

// A part standing on the substrate whose base edge is not quite level (a scan, a CAD export cut a
// hair off the plane): each generatrix starting above the substrate starts on it instead,
// straight on from its first segment, so the first ring is laid h_min .. h_max above the substrate
// where the deposit rests, not above the edge. The gap is below h_min / 2 (a larger one is refused
// as a base that is not level), so no point lands on the extension.
void extendToSubstrate(Generatrices& g, double substrateZ)
{
  for (size_t k = 0; k < g.lines.size(); ++k) {
    Polyline& line = g.lines[k];
    if (line.size() < 2 || !(line[0].z() > substrateZ + 1e-9)) continue;
    const Vec3 down = (line[0] - line[1]).normalized();
    if (!(down.z() < -1e-3)) continue;
    line.insert(line.begin(), line[0] + (substrateZ - line[0].z()) / down.z() * down);
    if (k < g.normals.size() && !g.normals[k].empty())
      g.normals[k].insert(g.normals[k].begin(), g.normals[k][0]);
  }
}

// The same on a substrate mesh (a scanned warped plate, a pipe): each generatrix starts where it meets
// the surface, straight on from its first segment: moved down onto it from just above, or up onto it
// where the base edge dips under it (a nominal flat base on a bowed plate). A start within 0.01 mm
// of the surface, or a surface not met within `reach` mm, leaves the generatrix as it is.
void extendToSubstrateMesh(Generatrices& g, const SubstrateSurface& substrate, double reach)
{
  for (size_t k = 0; k < g.lines.size(); ++k) {
    Polyline& line = g.lines[k];
    if (line.size() < 2) continue;
    const Vec3 up = (line[1] - line[0]).normalized();
    const double depth = substrate.depthBelow(line[0], up, reach, reach);
    if (!std::isfinite(depth) || std::abs(depth) < 0.01 || std::abs(depth) > reach) continue;
    const Vec3 start = line[0] - depth * up;
    if (depth > 0.0) {
      line.insert(line.begin(), start);
      if (k < g.normals.size() && !g.normals[k].empty())
        g.normals[k].insert(g.normals[k].begin(), g.normals[k][0]);
    } else if (-depth < 0.5 * (line[1] - line[0]).norm()) {
      line[0] = start;
    }
  }
}

bool onSubstrateMesh(const PlanRequest& request)
{
  return request.substrate && !request.substrate->isPlane();
}

// Closure point, generatrices, spiral and process channels of a part whose field is computed.
void finishMonoBranch(const PluginRegistry& registry, const PlanRequest& request, const Settings& settings,
                      PlanOutput& out, StageClock& clock, Progress& progress)
{
  if (out.topology.partClass != PartClass::Open) {
    const ClosureFinderPlugin& finder = registry.closureFinder(request.closureFinderId);
    SubProgress cp(progress, 0.3, 0.35, "closure point");
    out.closure = finder.find({request.mesh, out.topology.lower.vertices, &out.field},
                              paramsFor(request, request.closureFinderId), cp);
    out.hasClosure = true;
    out.warnings.insert(out.warnings.end(), out.closure.warnings.begin(), out.closure.warnings.end());
    clock.lap("closure");
  }
  progress.checkCancel();

  const DecomposerPlugin& decomposer = *settings.decomposer;
  DecomposeInput input{request.mesh,
                       out.topology.partClass,
                       out.topology.lower,
                       out.topology.upper,
                       out.hasClosure ? std::optional<Vec3>(out.closure.point) : std::nullopt,
                       &out.field};
  input.window = {settings.spiral.hMin, settings.spiral.hMax,
                  settings.spiral.heightTolerance * settings.spiral.h, settings.process.beadWidth};
  input.spiral = &settings.spiral;
  input.substrate = request.substrate.get();
  SubProgress dp(progress, 0.35, 0.8, "generatrices");
  DecomposeResult decomposition = decomposer.decompose(input, settings.decomposerParams, dp);
  out.generatrices = std::move(decomposition.generatrices);
  out.warnings.insert(out.warnings.end(), decomposition.warnings.begin(), decomposition.warnings.end());
  out.layers = std::move(decomposition.layers);
  if (decomposition.path) {
    out.spiral = std::move(*decomposition.path);
    clock.lap("decomposition");
  } else {
    if (request.baseSupportGap > 0.0)
      extendBelowBase(out.generatrices, request.baseSupportGap);
    else if (!onSubstrateMesh(request))
      extendToSubstrate(out.generatrices, request.substrateZ);
    else
      extendToSubstrateMesh(out.generatrices, *request.substrate, settings.spiral.hMax);
    clock.lap("decomposition");
    SubProgress sp(progress, 0.8, 0.95, "spiral");
    out.spiral = buildSpiral(out.generatrices, settings.spiral, sp);
    clock.lap("spiral");
  }
  out.process = applyProcess(out.spiral.trajectory, settings.process);
  if (!out.process.violations.empty()) {
    const ProcessViolation& first = out.process.violations.front();
    out.warnings.push_back(
        std::to_string(out.process.violations.size()) +
        " point(s) need speeds outside the process limits and were clamped to them (first: point " +
        std::to_string(first.point) + ", " + processViolationName(first.kind) + ")");
  }
  clock.lap("process");
  out.paths = {wholePathSummary(out)};
  out.paths[0].area = request.report.area;
}

// Contours shorter than this are not branches: a wall narrower than the bead cannot stand on its
// own, and loops under 5 % of the base are the noise of a field's extremum.
double branchPerimeter(const PlanOutput& out, const Settings& settings)
{
  return std::max(kPi * settings.process.beadWidth, 0.05 * out.topology.lower.length);
}

DepositCheckSettings depositSettings(const PlanRequest& request, const Settings& settings)
{
  DepositCheckSettings d;
  d.substrateZ = request.substrateZ;
  d.substrate = request.substrate;
  d.hMin = settings.spiral.hMin;
  d.hMax = settings.spiral.hMax;
  d.tolerance = settings.spiral.heightTolerance * settings.spiral.h;
  d.beadWidth = settings.process.beadWidth;
  return d;
}

// The verdict: the trajectory judged on its own, each sub-path told how many of its points failed.
void judgeDeposits(const PlanRequest& request, const Settings& settings, PlanOutput& out, Progress& progress)
{
  SubProgress p(progress, 0.95, 1.0, "deposit check");
  out.deposits = checkDeposits(out.spiral.trajectory, &request.mesh, depositSettings(request, settings), p);
  for (PathSummary& path : out.paths) {
    path.depositFlags = 0;
    for (const DepositFlag& f : out.deposits.flags)
      if (f.point >= path.firstPoint && f.point < path.firstPoint + path.pointCount) ++path.depositFlags;
  }
}

// A thin-walled solid planned on its mid-surface; the solid's own refusals (a bulk body) and its
// mid-surface's (a flange, a hole) name the solid, so the user knows which surface was judged.
PlanOutput planSolid(const PluginRegistry& registry, const PlanRequest& request, const Settings& settings,
                     Progress& progress)
{
  progress.report(0.0, "mid-surface of the solid");
  const auto start = std::chrono::steady_clock::now();
  SolidSurface surface = plannableMidSurface(request.mesh, settings.process.beadWidth);
  SolidWall& wall = surface.wall;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  PlanRequest mid(*wall.midSurface, surface.report, request);
  mid.midSurfaceOfSolid = false;
  PlanOutput out;
  try {
    out = planPart(registry, mid, progress);
  } catch (const InputError& e) {
    std::ostringstream what;
    what << std::fixed << std::setprecision(2) << "the part is a thin-walled solid (wall "
         << wall.thickness.median << " mm thick) but its mid-surface cannot be planned: " << e.what();
    throw InputError(what.str(), e.hint());
  }
  out.timings.insert(out.timings.begin(), {"mid-surface", seconds});
  out.warnings.insert(out.warnings.begin(), wall.warnings.begin(), wall.warnings.end());
  out.solid = std::move(wall);
  return out;
}

}  // namespace

PlanOutput planMonoBranch(const PluginRegistry& registry, const PlanRequest& request, Progress& progress)
{
  const Settings settings = settingsFor(registry, request);
  PlanOutput out;
  StageClock clock(out.timings);
  out.topology =
      findPartTopology(request.report, request.mesh, request.substrateZ, request.lowerLoopOverride);
  checkUpperEdge(out.topology, settings);
  clock.lap("topology");
  computeField(request, out, progress);
  clock.lap("field");
  finishMonoBranch(registry, request, settings, out, clock, progress);
  return out;
}

PlanOutput planPart(const PluginRegistry& registry, const PlanRequest& request, Progress& progress)
{
  const Settings settings = settingsFor(registry, request);
  if (request.midSurfaceOfSolid && isClosedSolid(request.report))
    return planSolid(registry, request, settings, progress);
  PlanOutput out;
  StageClock clock(out.timings);
  out.topology = findPartTopology(request.report, request.mesh, request.substrateZ, request.lowerLoopOverride,
                                  /*allowBranches=*/true);
  // Half the thinnest bead: a wider gap leaves the first ring in the air or under the plate.
  if (onSubstrateMesh(request)) {
    standOnSubstrateMesh(out.topology, request.report, request.mesh, *request.substrate,
                         request.lowerLoopOverride, 0.5 * settings.spiral.hMin);
  } else {
    requireOnSubstrate(out.topology, request.substrateZ, 0.5 * settings.spiral.hMin);
    requireLevelBase(out.topology, request.substrateZ, 0.5 * settings.spiral.hMin);
  }
  checkUpperEdge(out.topology, settings);
  clock.lap("topology");
  const double perimeter = branchPerimeter(out, settings);
  bool branches = out.topology.branched;
  // Branches show in the geodesic distance from the base (000_dbb97c2716e10cc3.txt §3.4.3): a mono-branch
  // part has one contour per level. A closed part plans with that field; an open part's harmonic field cannot
  // show them (a capped arm holds it nearly constant, with no saddle), so the distance is computed for it
  // too.
  std::vector<double> distance;
  if (!branches) {
    computeField(request, out, progress);
    if (out.fieldKind != "geodesic_distance") {
      SubProgress dp(progress, 0.3, 0.3, "geodesic distance from the base");
      distance = heatGeodesicDistance(request.mesh, out.topology.lower.vertices, HeatDistanceOptions{}, dp);
    }
    const std::vector<double>& field = distance.empty() ? out.field : distance;
    BranchScanOptions scan;
    scan.minPerimeter = perimeter;
    SubProgress bp(progress, 0.3, 0.3, "branches");
    branches = findFirstBranchSplit(request.mesh, field, highestValueOn(out.topology.lower.vertices, field),
                                    scan, bp)
                   .found;
    clock.lap("field");
  }
  if (!branches) {
    finishMonoBranch(registry, request, settings, out, clock, progress);
    judgeDeposits(request, settings, out, progress);
    clock.lap("deposit check");
    return out;
  }

  BranchSplitOptions split;
  split.minPerimeter = perimeter;
  split.nominalHeight = settings.spiral.h;
  split.thinnestDeposit = settings.spiral.hMin;
  const std::vector<double>* known =
      !distance.empty() ? &distance : (out.fieldKind == "geodesic_distance" ? &out.field : nullptr);
  SubProgress sp(progress, 0.0, 0.3, "branches");
  BranchDecomposition pieces =
      splitIntoMonoBranches(request.mesh, out.topology.lower.vertices, known, split, sp);
  clock.lap("branches");
  if (pieces.pieces.size() < 2) {
    if (out.topology.branched)
      refuseUnbranchedPart(request.report.boundaryLoops, perimeter, settings.process.beadWidth);
    finishMonoBranch(registry, request, settings, out, clock, progress);
    judgeDeposits(request, settings, out, progress);
    clock.lap("deposit check");
    return out;
  }
  SubProgress pp(progress, 0.3, 0.95, "sub-parts");
  planBranchPieces(registry, request, std::move(pieces), out, pp);
  clock.lap("sub-parts");
  judgeDeposits(request, settings, out, progress);
  clock.lap("deposit check");
  progress.report(1.0, "done");
  return out;
}

DepositCheckReport checkPlannedDeposits(const PluginRegistry& registry, const PlanRequest& request,
                                        const Trajectory& path, bool againstSurface, Progress& progress)
{
  const Settings settings = settingsFor(registry, request);
  return checkDeposits(path, againstSurface ? &request.mesh : nullptr, depositSettings(request, settings),
                       progress);
}

}  // namespace spira
