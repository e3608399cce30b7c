#include <chrono>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>

#include <nlohmann/json.hpp>

#include "builtin_plugins.h"
#include "cli_common.h"
#include "part_loading.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/io/import_service.h"
#include "spira/mesh/thin_wall.h"
#include "spira/path/process_model.h"
#include "spira/planning/solid_wall.h"
#include "spira/plugin/param_cli.h"
#include "spira/plugin/plugin_registry.h"
#include "spira/skeleton/mcf_skeleton.h"

namespace spira::cli {
namespace {

void printTiming(const ImportedPart& part, std::ostream& out)
{
  out << std::fixed << std::setprecision(3) << "timing: read " << part.seconds.read << " s, weld "
      << part.seconds.weld << " s, validate " << part.seconds.validate << " s, total " << part.seconds.total()
      << " s\n";
}

// The --skeleton section: the curve skeleton, or why it could not be computed (the rest of the
// report still stands).
struct SkeletonSection {
  std::optional<SkeletonResult> result;
  std::string error, hint;
  double seconds = 0.0;
};

SkeletonSection computeSkeletonSection(const TriangleMesh& mesh)
{
  SkeletonSection s;
  NullProgress progress;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    s.result = computeCurveSkeleton(mesh, SkeletonOptions{}, progress);
  } catch (const InternalError&) {
    throw;  // a bug, reported as one (exit 1), not as a finding about the part
  } catch (const Error& e) {
    s.error = e.what();
    s.hint = e.hint();
  }
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return s;
}

nlohmann::json pointJson(const Vec3& p)
{
  return nlohmann::json::array({p.x(), p.y(), p.z()});
}

nlohmann::json skeletonJson(const SkeletonSection& s)
{
  if (!s.result) return {{"error", s.error}, {"hint", s.hint}};
  const CurveSkeleton& k = s.result->skeleton;
  nlohmann::json j;
  j["branch_count"] = k.branchCount();
  j["branch_points"] = nlohmann::json::array();
  for (const Vec3& p : k.branchPoints) j["branch_points"].push_back(pointJson(p));
  j["end_points"] = nlohmann::json::array();
  for (const Vec3& p : k.endPoints) j["end_points"].push_back(pointJson(p));
  j["loops"] = k.loops;
  j["mono_branch"] = k.monoBranch();
  j["monotone_in_z"] = k.monotoneInZ;
  j["branches"] = nlohmann::json::array();
  for (const Polyline& b : k.branches) {
    nlohmann::json line = nlohmann::json::array();
    for (const Vec3& p : b) line.push_back(pointJson(p));
    j["branches"].push_back(line);
  }
  j["nodes"] = k.graph.nodes.size();
  j["contraction_steps"] = s.result->iterations;
  j["converged"] = s.result->converged;
  j["free_edges_capped"] = s.result->capsAdded;
  j["warnings"] = s.result->warnings;
  return j;
}

void printSkeleton(const SkeletonSection& s, std::ostream& out)
{
  if (!s.result) {
    out << "skeleton: not computed: " << s.error << "\n";
    if (!s.hint.empty()) out << "  hint: " << s.hint << "\n";
    return;
  }
  const CurveSkeleton& k = s.result->skeleton;
  out << std::setprecision(3) << std::fixed;
  out << "skeleton: " << k.branchCount() << " branch(es), " << k.branchPoints.size() << " branch point(s), "
      << k.loops << " loop(s), monotone in z: " << (k.monotoneInZ ? "yes" : "no") << " ("
      << (k.monoBranch() ? "mono-branch" : "multi-branch") << "; " << k.graph.nodes.size() << " nodes, "
      << s.result->iterations << " contraction steps, " << s.result->capsAdded << " free edge(s) capped)\n";
  for (const Vec3& p : k.branchPoints)
    out << "  branch point at (" << p.x() << ", " << p.y() << ", " << p.z() << ") mm\n";
  for (const auto& w : s.result->warnings) out << "warning: " << w << "\n";
}

// A watertight part: whether it is a thin wall Spira plans on its mid-surface, with the
// thickness against the default bead (plan --bead-width sets the one it is planned with).
struct SolidSection {
  ThinWallAnalysis analysis;
  MeshReport midReport;
  double beadWidth = ProcessSettings{}.beadWidth;
  std::vector<std::string> warnings;
  double seconds = 0.0;
};

std::optional<SolidSection> computeSolidSection(const ImportedPart& part)
{
  if (!isClosedSolid(part.report)) return std::nullopt;
  SolidSection s;
  const auto t0 = std::chrono::steady_clock::now();
  s.analysis = analyseClosedSolid(part.mesh);
  if (s.analysis.kind == SolidKind::ThinWalled) {
    s.midReport = validateMesh(s.analysis.midSurface);
    s.warnings = beadWidthWarnings(s.analysis.thickness, s.beadWidth);
  }
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return s;
}

nlohmann::json solidJson(const SolidSection& s)
{
  const ThinWallAnalysis& a = s.analysis;
  const bool thin = a.kind == SolidKind::ThinWalled;
  nlohmann::json j{{"kind", thin ? "thin_walled_solid" : "bulk_solid"},
                   {"reason", a.reason},
                   {"wall_thickness_mm",
                    {{"median", a.thickness.median},
                     {"thinnest", a.thickness.thinnest},
                     {"thickest", a.thickness.thickest}}},
                   {"wall_area_fraction", a.wallAreaFraction},
                   {"bead_width_mm", s.beadWidth},
                   {"warnings", s.warnings}};
  j["planned_on"] = thin ? "mid_surface" : "refused";
  if (thin)
    j["mid_surface"] = {{"faces", a.midSurface.faceCount()},
                        {"boundary_loops", s.midReport.boundaryLoops.size()},
                        {"class", s.midReport.className()}};
  return j;
}

void printSolid(const SolidSection& s, std::ostream& out)
{
  const ThinWallAnalysis& a = s.analysis;
  out << "solid: " << a.reason << "\n";
  if (a.kind == SolidKind::ThinWalled)
    out << "  planned on its mid-surface: one skin of " << a.skinFaces << " faces moved in by half the wall, "
        << s.midReport.boundaryLoops.size() << " boundary loop(s) (" << s.midReport.className()
        << "); bead width " << std::fixed << std::setprecision(2) << s.beadWidth
        << " mm (default; plan --bead-width sets it)\n";
  else
    out << "  refused by plan: give Spira the wall's mid-surface, or one of its skins, as a surface open at "
           "the base\n";
  for (const auto& w : s.warnings) out << "warning: " << w << "\n";
}

}  // namespace

int cmdInfo(const std::vector<std::string>& argv)
{
  const PluginRegistry& registry = builtinRegistry();
  ImporterFlags flags(registry);
  Args args = splitArgs(argv);
  if (args.takeSwitch("--help")) {
    std::cout
        << "usage: spira-cli info PART [--json] [--timing] [--skeleton] [importer flags]\n\n"
           "Imports PART (welded and validated as in the GUI) and prints mesh statistics, validation\n"
           "findings with positions, boundary loops (count, length, z-range), connected components and\n"
           "the open/closed classification. --json prints the same as JSON; --timing adds stage times.\n"
           "--skeleton adds the part's mean curvature flow curve skeleton: branch count, branch points,\n"
           "loops and whether it rises monotonically in z (free edges are capped for the computation).\n"
           "A watertight part is measured as a solid: its wall thickness, whether it is a thin wall that\n"
           "'plan' lays on its mid-surface, or a solid body it refuses (docs/thin-walled-solids.md).\n"
        << paramFlagsHelp(flags.targets());
    return kExitOk;
  }
  const bool json = args.takeSwitch("--json");
  const bool timing = args.takeSwitch("--timing");
  const bool skeleton = args.takeSwitch("--skeleton");
  args.rest = takeParamFlags(args.rest, flags.targets());
  const auto positional = args.finish("info", 1, 1);
  const std::string& file = positional[0];

  NullProgress progress;
  const ImportedPart part = flags.import(file, progress);
  const std::optional<SkeletonSection> skeletonSection =
      skeleton ? std::optional<SkeletonSection>(computeSkeletonSection(part.mesh)) : std::nullopt;
  const std::optional<SolidSection> solid = computeSolidSection(part);

  if (json) {
    nlohmann::json j = part.report.toJson();
    j["file"] = file;
    j["importer"] = part.importerId;
    j["source_unit"] = std::string(lengthUnitSymbol(part.sourceUnit));
    j["weld"] = {{"input_vertices", part.weld.inputVertices},
                 {"output_vertices", part.weld.outputVertices},
                 {"tolerance_mm", part.weld.tolerance}};
    j["warnings"] = part.warnings;
    if (timing)
      j["timings_s"] = {{"read", part.seconds.read},
                        {"weld", part.seconds.weld},
                        {"validate", part.seconds.validate},
                        {"total", part.seconds.total()}};
    if (solid) {
      j["solid"] = solidJson(*solid);
      if (timing) j["timings_s"]["solid"] = solid->seconds;
    }
    if (skeletonSection) {
      j["skeleton"] = skeletonJson(*skeletonSection);
      if (timing) j["timings_s"]["skeleton"] = skeletonSection->seconds;
    }
    std::cout << j.dump(2) << "\n";
    return kExitOk;
  }
  std::cout << "file: " << file << " (" << part.importerId << ", coordinates in "
            << lengthUnitSymbol(part.sourceUnit) << ", shown in mm)\n";
  std::cout << "welded " << part.weld.inputVertices << " -> " << part.weld.outputVertices
            << " vertices (tolerance " << part.weld.tolerance << " mm)\n";
  std::cout << part.report.toText();
  for (const auto& w : part.warnings) std::cout << "warning: " << w << "\n";
  if (solid) printSolid(*solid, std::cout);
  if (skeletonSection) printSkeleton(*skeletonSection, std::cout);
  if (timing) printTiming(part, std::cout);
  if (timing && solid) std::cout << "timing: solid " << solid->seconds << " s\n";
  if (timing && skeletonSection) std::cout << "timing: skeleton " << skeletonSection->seconds << " s\n";
  return kExitOk;
}

}  // namespace spira::cli
