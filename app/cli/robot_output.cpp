#include "robot_output.h"

#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>

#include "cli_common.h"
#include "spira/pipeline/program_header.h"

namespace spira::cli {

const ExporterPlugin& exporterFor(const PluginRegistry& registry, const std::string& format)
{
  if (const ExporterPlugin* e = exporterForFormat(registry, format)) return *e;
  throw UsageError("unknown program format '" + format + "'", "use one of: " + exporterFormatList(registry));
}

std::map<std::string, std::string> programHeader(const std::string& partFile, const std::string& cellFile,
                                                 const PlanReportSummary& r)
{
  const std::string cell = cellFile.empty() ? std::string() : r.cell.empty() ? cellFile : r.cell;
  return spira::programHeader(std::filesystem::path(partFile).filename().string(), cell, r, programTime());
}

namespace {

// A turn on the spot needs an infinite axis speed.
std::string number(double v)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(3);
  if (std::isfinite(v))
    s << v;
  else
    s << "infinite";
  return s.str();
}

std::string indexText(const std::optional<std::int64_t>& i)
{
  return i ? std::to_string(*i) : std::string("null");
}

void printJointSpeed(const JointSpeedRecord& js, std::ostream& out)
{
  if (js.pointsOverLimit == 0) return;
  out << "joint speed: " << js.pointsOverLimit
      << " point(s) need an axis past its speed limit at the planned travel speed (" << js.axis << " at "
      << number(js.maxPercent) << " % at point " << indexText(js.point) << ")";
  if (!js.slowdown) {
    out << ": INFEASIBLE (--allow-slowdown lets the controller slow down there)\n";
    return;
  }
  const SlowdownRecord& sd = *js.slowdown;
  out << "; the controller slows down there and the deposit thickens (" << sd.heightModel << ") to "
      << number(sd.maxHeight.value_or(std::numeric_limits<double>::quiet_NaN())) << " mm at most, at "
      << sd.outsideWindow << " point(s) outside the window\n";
}

}  // namespace

void printMotionSummary(const MotionStageReport& r, std::ostream& out)
{
  out << std::fixed << std::setprecision(3);
  out << "cell " << r.cell << ": " << (r.reachable ? "reachable" : "UNREACHABLE") << " ("
      << r.unreachablePoints << " point(s) out of reach or limits), configuration " << r.configuration
      << "\n";
  out << "joint-limit margin " << r.minLimitMarginDeg << " deg (" << r.minLimitMarginAxis
      << "), dexterity >= " << r.minDexterity << ", joint speed <= " << 100.0 * r.maxJointSpeedRatio
      << " % of the limit (" << r.maxJointSpeedAxis << ")\n";
  if (r.positionerRange)
    for (const auto& [axis, range] : *r.positionerRange)
      out << "positioner " << axis << " " << range[0] << " .. " << range[1] << " deg\n";
  printJointSpeed(r.jointSpeed, out);
  out << "torch collisions: " << r.collisionsDetected << " detected, " << r.collisionsResolved
      << " resolved by tilting, " << r.collisions << " left\n";
  out << "robot links: " << r.robotCollisions << " of " << r.robotPointsChecked << " checked points collide";
  if (!r.robotCollisionLinks.empty()) out << " (" << nlohmann::json(r.robotCollisionLinks).dump() << ")";
  out << "\n";
  for (const std::string& w : r.cellWarnings) out << "warning: " << w << "\n";
}

void printExportSummary(const ExportOutcome& e, std::ostream& out)
{
  out << "program: " << e.prep.pointsIn << " planned points -> " << e.robotTargets
      << " robot targets (chord <= " << std::setprecision(4) << e.prep.maxChordDeviation << " mm), "
      << e.result.files.size() << " file(s)"
      << (e.subPaths > 1 ? ", " + std::to_string(e.subPaths) + " sub-paths (one arc each)" : std::string())
      << (e.dwells > 0 ? ", " + std::to_string(e.dwells) + " dwell(s) (arc off, torch lifted)"
                       : std::string())
      << ":";
  for (const auto& f : e.result.files) out << " " << f.filename().string();
  out << "\n";
  for (const auto& w : e.result.warnings) out << "warning: " << w << "\n";
}

}  // namespace spira::cli
