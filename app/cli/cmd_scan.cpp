// spira-cli scan-compare: a scan registered to the part and its deviation from it.
#include <chrono>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "builtin_plugins.h"
#include "cli_common.h"
#include "part_loading.h"
#include "plan_folder.h"
#include "quality_outputs.h"
#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/base/output_set.h"
#include "spira/base/units.h"
#include "spira/plugin/param_cli.h"
#include "spira/scan/pair_alignment.h"
#include "spira/scan/scan_alignment.h"
#include "spira/scan/scan_deviation.h"
#include "spira/scan/scan_processing.h"
#include "spira/scan/scan_reader.h"
#include "spira/scan/scan_simulator.h"
#include "spira/scan/scan_writer.h"

namespace spira::cli {
namespace {

constexpr const char* kHelp =
    "usage: spira-cli scan-compare PART SCAN -o DIR [--no-align] [--voxel MM] [--align-voxel MM]\n"
    "                              [--max-distance MM] [--outlier-stddev X] [--scan-scale X] [--pairs FILE]\n"
    "                              [--plan PLAN_DIR --at INDEX [--bead-width MM]] [importer flags]\n\n"
    "Reads SCAN (a point cloud: .ply, .pcd, .xyz/.csv/.txt/.asc columns x y z [nx ny nz]; or a mesh), "
    "removes\n"
    "its stray points (statistical outlier removal, --outlier-stddev, 0 for none; --voxel thins it to one "
    "point\n"
    "per cell first), registers it to PART by point-to-plane ICP from where it lies (--no-align: it was "
    "taken\n"
    "in the part's frame), and measures every point's signed distance to the part (positive outside).\n"
    "Writes DIR/aligned_scan.ply (the scan moved onto the part, with its deviation per point),\n"
    "DIR/deviation.csv (index,x,y,z,deviation_mm) and DIR/deviation.json (the transform, the residual,\n"
    "mean, RMS, 95th percentile and a histogram). --align-voxel MM thins the scan for the fit (default 1),\n"
    "--max-distance MM is the farthest a point may lie from the part to count in the fit (default 1).\n"
    "A scan far larger or smaller than the part is refused with its likely unit: --scan-scale X multiplies\n"
    "its coordinates. --pairs FILE: three or more places picked on the part and on the scan, one pair per\n"
    "line (part_x,part_y,part_z,scan_x,scan_y,scan_z), fitted by a rigid motion that starts the ICP (with\n"
    "--no-align, the motion alone); pairs no rigid motion matches within 5 mm are refused.\n"
    "Exit 3 for a scan that cannot be read, is too small or does not overlap the part.\n"
    "With --plan PLAN_DIR (the plan PART was built from) and --at INDEX (its points deposited when the scan\n"
    "was taken), the quality indices (docs/scans.md; 1 = as planned, 0.92 = off by 8 % of a bead height):\n"
    "trajectory (the plan against the part), process (the measured top edge against the plan) and global\n"
    "(the scan against the part), in DIR/quality.csv (per plan point), deviation.csv's global_index and\n"
    "deviation.json's quality_indices. PART is moved as the plan moved it (report.json's dropped_mm), and\n"
    "everything is in the plan's frame. --bead-width MM: the bead the top edge is measured with (default\n"
    "5.2).\n";

// Hand-picked points are a few tenths of a millimetre off at best; a pair several millimetres off was
// picked at another place.
constexpr double kPairToleranceMm = 5.0;

nlohmann::json transformJson(const Transform& T)
{
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 4; ++r) rows.push_back({T(r, 0), T(r, 1), T(r, 2), T(r, 3)});
  return rows;
}

nlohmann::json statsJson(const DeviationStats& s)
{
  return {{"count", s.count},
          {"mean_mm", s.mean},
          {"rms_mm", s.rms},
          {"p95_mm", s.p95},
          {"min_mm", s.min},
          {"max_mm", s.max},
          {"histogram", {{"min_mm", s.binMin}, {"bin_mm", s.binWidth}, {"counts", s.histogram}}}};
}

std::string deviationCsv(const PointCloud& scan, const std::vector<double>& deviation,
                         const std::vector<double>* global)
{
  std::string out = global ? "index,x,y,z,deviation_mm,global_index\n" : "index,x,y,z,deviation_mm\n";
  out.reserve(out.size() + scan.size() * 64);
  for (size_t i = 0; i < scan.size(); ++i) {
    appendNumber(out, static_cast<long long>(i));
    for (int k = 0; k < 3; ++k) {
      out += ',';
      appendNumber(out, scan.points[i][k]);
    }
    out += ',';
    appendNumber(out, deviation[i]);
    if (global) {
      out += ',';
      appendNumber(out, (*global)[i]);
    }
    out += '\n';
  }
  return out;
}

}  // namespace

int cmdScanCompare(const std::vector<std::string>& argv)
{
  const PluginRegistry& registry = builtinRegistry();
  ImporterFlags flags(registry);
  Args args = splitArgs(argv);
  if (args.takeSwitch("--help")) {
    std::cout << kHelp << paramFlagsHelp(flags.targets());
    return kExitOk;
  }
  const std::string outText = args.takeOption("-o");
  const bool align = !args.takeSwitch("--no-align");
  ScanFilterSettings filter;
  filter.voxelMm = positiveFlag("--voxel", args.takeOption("--voxel"), 0.0, true);
  filter.outlierStddev = positiveFlag("--outlier-stddev", args.takeOption("--outlier-stddev"), 3.0, true);
  AlignSettings alignment;
  alignment.voxelMm = positiveFlag("--align-voxel", args.takeOption("--align-voxel"), 1.0, false);
  alignment.finalDistanceMm = positiveFlag("--max-distance", args.takeOption("--max-distance"), 1.0, false);
  alignment.startDistanceMm = std::max(10.0, alignment.finalDistanceMm);
  const double scale = positiveFlag("--scan-scale", args.takeOption("--scan-scale"), 1.0, false);
  const std::string pairsFile = args.takeOption("--pairs");
  const std::string planText = args.takeOption("--plan");
  const std::string atText = args.takeOption("--at");
  const std::string beadText = args.takeOption("--bead-width");
  args.rest = takeParamFlags(args.rest, flags.targets());
  const auto positional = args.finish("scan-compare", 2, 2);
  if (outText.empty())
    throw UsageError("scan-compare needs -o DIR", "add -o DIR for the aligned scan and deviation");
  if (planText.empty() && !atText.empty())
    throw UsageError("--at needs --plan: the index counts the points of a plan",
                     "add --plan PLAN_DIR (the plan the part was built from), or leave --at out");
  if (!planText.empty() && atText.empty())
    throw UsageError("--plan needs --at INDEX: how much of the plan was built when the scan was taken",
                     "add --at and the number of the plan's points deposited, e.g. --at 5000");
  if (planText.empty() && !beadText.empty())
    throw UsageError("--bead-width is for the quality indices, which need --plan",
                     "add --plan PLAN_DIR --at INDEX, or leave --bead-width out");
  const double beadWidth = beadWidthFlag(beadText);
  const std::filesystem::path outDir(outText);
  ensureWritableDirectory(outDir);
  std::optional<PlanFolder> plan;
  size_t at = 0;
  if (!planText.empty()) {
    plan = readPlanFolder(planText);
    at = atFlag(atText, plan->trajectory);
  }

  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const auto since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  NullProgress progress;
  ImportedPart part = flags.import(positional[0], progress);
  if (plan && plan->droppedMm != 0.0) {
    // The plan's points are where the plan put the part: the part, and the scan aligned to it, go there.
    for (Vec3& v : part.mesh.vertices) v.z() += plan->droppedMm;
    std::cout << "moved the part " << significantText(plan->droppedMm, 6)
              << " mm along z, as the plan dropped it onto the substrate\n";
  }
  if (plan && plan->levelledBase)
    std::cerr << "note: the plan cut the part's base level (--level-base); the part is compared as its file "
                 "holds it, the cut-off sliver below the plate\n";
  auto lap = Clock::now();
  PointCloud scan = readScan(registry, positional[1], progress);
  if (scale != 1.0)
    for (Vec3& p : scan.points) p *= scale;
  const double readSeconds = since(lap);
  if (const auto unit = scanUnitHint(boundsOf(scan), part.mesh.bounds()))
    throw InputError("'" + positional[1] + "': " + *unit,
                     "give the scale that makes it mm with --scan-scale, or export the scan in mm");
  lap = Clock::now();
  ScanFilterReport filtered;
  scan = filterScan(scan, filter, &filtered);
  const double filterSeconds = since(lap);
  lap = Clock::now();
  AlignResult fit;
  std::optional<PairFit> picked;
  if (!pairsFile.empty()) {
    picked = fitPointPairs(parsePointPairs(readFile(pairsFile), "'" + pairsFile + "'"), kPairToleranceMm);
    fit.T_part_scan = picked->T_part_scan;
  }
  if (align) fit = alignScan(scan, part.mesh, fit.T_part_scan, alignment, progress);
  if (align || picked) scan = transformed(scan, fit.T_part_scan);
  const double alignSeconds = since(lap);
  lap = Clock::now();
  const std::vector<double> deviation = scanDeviation(scan, part.mesh, progress);
  const DeviationStats stats = deviationStats(deviation);
  const double deviationSeconds = since(lap);
  std::optional<CompareQuality> quality;
  if (plan) {
    lap = Clock::now();
    quality = compareQuality(*plan, at, part.mesh, positional[0], scan, deviation, beadWidth);
  }
  const double qualitySeconds = plan ? since(lap) : 0.0;

  nlohmann::json j;
  j["part"] = positional[0];
  j["scan"] = positional[1];
  j["points_read"] = filtered.read;
  j["points_after_voxel"] = filtered.afterVoxel;
  j["outliers_removed"] = filtered.outliers;
  j["points"] = scan.size();
  if (scale != 1.0) j["scan_scale"] = scale;
  if (align) {
    const Eigen::AngleAxisd turn(fit.T_part_scan.linear());
    j["alignment"] = {{"T_part_scan", transformJson(fit.T_part_scan)},
                      {"translation_mm", fit.T_part_scan.translation().norm()},
                      {"rotation_deg", radToDeg(turn.angle())},
                      {"rms_mm", fit.rmsMm},
                      {"inlier_fraction", fit.inlierFraction},
                      {"points_used", fit.pointsUsed},
                      {"converged", fit.converged}};
  } else {
    j["alignment"] = nullptr;
  }
  if (picked)
    j["picked_pairs"] = {{"file", pairsFile},
                         {"T_part_scan", transformJson(picked->T_part_scan)},
                         {"rms_mm", picked->rmsMm},
                         {"residuals_mm", picked->residualsMm}};
  j["deviation"] = statsJson(stats);
  if (quality) j["quality_indices"] = qualityJson(planText, *quality);
  j["timings_s"] = {{"read", readSeconds},
                    {"filter", filterSeconds},
                    {"align", alignSeconds},
                    {"deviation", deviationSeconds},
                    {"total", since(start)}};
  if (quality) j["timings_s"]["quality_indices"] = qualitySeconds;
  std::vector<OutputFile> files = {
      {"aligned_scan.ply", pointCloudPly(scan, &deviation, "deviation")},
      {"deviation.csv", deviationCsv(scan, deviation, quality ? &quality->global : nullptr)},
      {"deviation.json", j.dump(2) + "\n"}};
  if (quality) files.push_back({"quality.csv", qualityCsv(plan->trajectory, *quality)});
  replaceOutputSet(outDir, OutputKind::Scan, files);

  std::cout << "scan " << positional[1] << ": " << filtered.read << " points, " << filtered.outliers
            << " stray point(s) removed, " << scan.size() << " compared\n";
  if (picked)
    std::cout << "picked pairs: " << picked->residualsMm.size() << ", matched within "
              << significantText(picked->rmsMm, 3) << " mm RMS" << (align ? ", the fit's starting guess" : "")
              << "\n";
  if (align)
    std::cout << "aligned: moved " << significantText(fit.T_part_scan.translation().norm(), 4) << " mm and "
              << significantText(radToDeg(Eigen::AngleAxisd(fit.T_part_scan.linear()).angle()), 4)
              << " deg onto the part; residual " << significantText(fit.rmsMm, 3) << " mm RMS over "
              << significantText(100.0 * fit.inlierFraction, 4) << " % of the points\n";
  std::cout << "deviation from the part (mm, + outside): mean " << significantText(stats.mean, 3) << ", RMS "
            << significantText(stats.rms, 3) << ", 95 % within " << significantText(stats.p95, 3) << ", from "
            << significantText(stats.min, 3) << " to " << significantText(stats.max, 3) << "\n";
  if (quality) std::cout << qualitySummary(*quality) << "\n";
  std::cout << "wrote " << (outDir / "aligned_scan.ply").string() << ", deviation.csv"
            << (quality ? ", deviation.json and quality.csv\n" : " and deviation.json\n");
  return kExitOk;
}

namespace {

constexpr const char* kSimHelp =
    "usage: spira-cli scan-sim PART -o SCAN.ply|.xyz [--spacing MM] [--noise MM] [--scale X]\n"
    "                          [--move DX,DY,DZ[,RX,RY,RZ]] [--seed N] [importer flags]\n"
    "       spira-cli scan-sim PLAN_DIR --at INDEX --error KIND:PERCENT[@UNTIL%][,SIDE] -o SCAN.ply\n"
    "                          [--noise MM] [--bead-width MM] [--seed N]\n\n"
    "Writes a laser-line scan of PART made in code, for trying scan-compare without a scanner: points about\n"
    "--spacing mm apart on its surface (default 1), gaussian noise of --noise mm along the surface normal\n"
    "(default 0.05), the part grown by --scale about the centre of its base (default 1), and the whole scan\n"
    "moved by --move: DX,DY,DZ mm then a turn RX,RY,RZ deg about the part's centre (the scanner's frame off\n"
    "the part's). The same seed gives the same scan.\n"
    "With a plan folder: the wall of the plan as built to point INDEX, each bead's height off the plan by\n"
    "--error (uniform:-8% everywhere, or sag:-8%,-y on the side facing -y; @30% only over the first 30 % of\n"
    "the plan's points), scanned over its last three revolutions: the crown of each bead and both faces of "
    "the\n"
    "wall, in the part's frame. 'spira-cli resume' re-plans the rest from it.\n";

// "DX,DY,DZ[,RX,RY,RZ]": mm, then degrees about x, y and z (fixed axes, in that order) about `centre`.
Transform moveFlag(const std::string& text, const Vec3& centre)
{
  std::vector<double> v;
  size_t at = 0;
  while (at <= text.size()) {
    const size_t comma = std::min(text.find(',', at), text.size());
    v.push_back(finiteNumberFlag("--move", text.substr(at, comma - at), "--move 3,-2,1,0,0,5"));
    at = comma + 1;
  }
  if (v.size() != 3 && v.size() != 6)
    throw UsageError("--move " + text + " has " + std::to_string(v.size()) + " numbers",
                     "give DX,DY,DZ in mm, optionally then RX,RY,RZ in degrees, e.g. --move 3,-2,1,0,0,5");
  Transform T = Transform::Identity();
  if (v.size() == 6)
    T.linear() =
        (Eigen::AngleAxisd(degToRad(v[5]), Vec3::UnitZ()) * Eigen::AngleAxisd(degToRad(v[4]), Vec3::UnitY()) *
         Eigen::AngleAxisd(degToRad(v[3]), Vec3::UnitX()))
            .toRotationMatrix();
  T.translation() = centre - T.linear() * centre + Vec3(v[0], v[1], v[2]);
  return T;
}

std::string xyzText(const PointCloud& cloud)
{
  std::string out = "x,y,z\n";
  for (const Vec3& p : cloud.points) {
    for (int k = 0; k < 3; ++k) {
      appendNumber(out, p[k]);
      out += k < 2 ? ',' : '\n';
    }
  }
  return out;
}

}  // namespace

int cmdScanSim(const std::vector<std::string>& argv)
{
  const PluginRegistry& registry = builtinRegistry();
  ImporterFlags flags(registry);
  Args args = splitArgs(argv);
  if (args.takeSwitch("--help")) {
    std::cout << kSimHelp << paramFlagsHelp(flags.targets());
    return kExitOk;
  }
  const std::string outText = args.takeOption("-o");
  const double spacing = positiveFlag("--spacing", args.takeOption("--spacing"), 1.0, false);
  ScanErrors errors;
  errors.noiseMm = positiveFlag("--noise", args.takeOption("--noise"), 0.05, true);
  errors.scale = positiveFlag("--scale", args.takeOption("--scale"), 1.0, false);
  const std::string move = args.takeOption("--move");
  const std::string seedText = args.takeOption("--seed");
  const long long seed =
      seedText.empty() ? 1 : wholeNumberFlag("--seed", seedText, 0, 1000000000, "--seed 7");
  if (outText.empty())
    throw UsageError("scan-sim needs -o SCAN.ply", "add -o and the scan file to write (.ply or .xyz)");
  const std::filesystem::path out(outText);
  const std::string ext = out.extension().string();
  if (ext != ".ply" && ext != ".xyz")
    throw UsageError("cannot tell the scan format of '" + outText + "' from its extension",
                     "name the file .ply or .xyz");
  if (!args.rest.empty() && std::filesystem::is_directory(args.rest.front())) {
    if (ext != ".ply") throw UsageError("a plan's simulated scan is written as PLY", "name the file .ply");
    if (!move.empty() || errors.scale != 1.0)
      throw UsageError("--move and --scale are for a part's scan",
                       "give a plan's scan --at and --error instead");
    const std::string planDir = args.rest.front();
    return simulatePlanScan(args, planDir, out, errors.noiseMm, seed);
  }
  args.rest = takeParamFlags(args.rest, flags.targets());
  const auto positional = args.finish("scan-sim", 1, 1);
  NullProgress progress;
  const ImportedPart part = flags.import(positional[0], progress);
  const BoundingBox box = part.mesh.bounds();
  errors.scaleCentre = Vec3(box.center().x(), box.center().y(), box.min.z());
  if (!move.empty()) errors.misalignment = moveFlag(move, box.center());
  const size_t expected = size_t(part.mesh.area() / (spacing * spacing));
  if (expected > 20000000)
    throw InputError("about " + std::to_string(expected) + " points at " + significantText(spacing, 3) +
                         " mm over this part's " + significantText(part.mesh.area(), 4) + " mm^2",
                     "give a larger --spacing (at most 20 million points)");
  const PointCloud scan = simulateSurfaceScan(part.mesh, spacing, errors, std::uint64_t(seed));
  writeFileAtomically(out, ext == ".ply" ? pointCloudPly(scan) : xyzText(scan));
  std::cout << "wrote " << outText << ": " << scan.size() << " points of " << positional[0] << "\n";
  return kExitOk;
}

}  // namespace spira::cli
