#include "robot_output.h"

#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iomanip>
#include <ostream>
#include <sstream>

#include "cli_common.h"
#include "spira/pipeline/program_header.h"

namespace spira::cli {

namespace {

// When the program is written: now, or SOURCE_DATE_EPOCH (seconds since 1970-01-01 UTC, the
// reproducible-builds convention) when set, so that the same plan gives byte-identical programs.
std::time_t programTime()
{
  const char* epoch = std::getenv("SOURCE_DATE_EPOCH");
  if (!epoch || !*epoch) return std::time(nullptr);
  char* end = nullptr;
  const long long seconds = std::strtoll(epoch, &end, 10);
  if (*end != '\0' || seconds < 0)
    throw UsageError(
        "SOURCE_DATE_EPOCH must be a whole number of seconds since 1970, not '" + std::string(epoch) + "'",
        "unset it to date programs now, or give e.g. SOURCE_DATE_EPOCH=0");
  return static_cast<std::time_t>(seconds);
}

}  // namespace

const ExporterPlugin& exporterFor(const PluginRegistry& registry, const std::string& format)
{
  const std::string id = format.find('.') == std::string::npos ? "export." + format : format;
  const Plugin* p = registry.find(id);
  if (!p || p->kind() != PluginKind::Exporter) {
    std::string formats;
    for (const Plugin* e : registry.ofKind(PluginKind::Exporter))
      formats += (formats.empty() ? "" : ", ") + e->id().substr(e->id().find('.') + 1);
    throw UsageError("unknown program format '" + format + "'", "use one of: " + formats);
  }
  return registry.exporter(id);
}

std::map<std::string, std::string> programHeader(const std::string& partFile, const std::string& cellFile,
                                                 const PlanReportSummary& r)
{
  const std::string cell = cellFile.empty() ? std::string() : r.cell.empty() ? cellFile : r.cell;
  return spira::programHeader(std::filesystem::path(partFile).filename().string(), cell, r, programTime());
}

namespace {

// An infinite value (a turn on the spot) is stored as null.
std::string number(const nlohmann::json& v)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(3);
  if (v.is_number())
    s << v.get<double>();
  else
    s << "infinite";
  return s.str();
}

void printJointSpeed(const nlohmann::json& js, std::ostream& out)
{
  const size_t over = js.value("points_over_limit", size_t{0});
  if (over == 0) return;
  out << "joint speed: " << over
      << " point(s) need an axis past its speed limit at the planned travel speed (" << js.value("axis", "")
      << " at " << number(js["max_percent"]) << " % at point " << js["point"].dump() << ")";
  if (!js.contains("slowdown")) {
    out << ": INFEASIBLE (--allow-slowdown lets the controller slow down there)\n";
    return;
  }
  const nlohmann::json& sd = js["slowdown"];
  out << "; the controller slows down there and the deposit thickens (" << sd.value("height_model", "")
      << ") to " << number(sd["max_height_mm"]) << " mm at most, at " << sd.value("outside_window", size_t{0})
      << " point(s) outside the window\n";
}

}  // namespace

void printMotionSummary(const nlohmann::json& r, std::ostream& out)
{
  out << std::fixed << std::setprecision(3);
  out << "cell " << r.value("cell", "") << ": " << (r.value("reachable", false) ? "reachable" : "UNREACHABLE")
      << " (" << r.value("unreachable_points", 0) << " point(s) out of reach or limits), configuration "
      << r.value("configuration", "") << "\n";
  out << "joint-limit margin " << r.value("min_joint_limit_margin_deg", 0.0) << " deg ("
      << r.value("min_joint_limit_margin_axis", "") << "), dexterity >= " << r.value("min_dexterity", 0.0)
      << ", joint speed <= " << 100.0 * r.value("max_joint_speed_ratio", 0.0) << " % of the limit ("
      << r.value("max_joint_speed_axis", "") << ")\n";
  if (r.contains("positioner_range_deg"))
    for (const auto& [axis, range] : r["positioner_range_deg"].items())
      out << "positioner " << axis << " " << range[0].get<double>() << " .. " << range[1].get<double>()
          << " deg\n";
  printJointSpeed(r.value("joint_speed", nlohmann::json::object()), out);
  out << "torch collisions: " << r.value("collisions_detected", 0) << " detected, "
      << r.value("collisions_resolved", 0) << " resolved by tilting, " << r.value("collisions", 0)
      << " left\n";
  out << "robot links: " << r.value("robot_collisions", 0) << " of " << r.value("robot_points_checked", 0)
      << " checked points collide";
  if (r.contains("robot_collision_links") && !r["robot_collision_links"].empty())
    out << " (" << r["robot_collision_links"].dump() << ")";
  out << "\n";
  if (r.contains("cell_warnings"))
    for (const auto& w : r["cell_warnings"]) out << "warning: " << w.get<std::string>() << "\n";
}

void printExportSummary(const ExportOutcome& e, std::ostream& out)
{
  out << "program: " << e.prep.pointsIn << " planned points -> " << e.robotTargets
      << " robot targets (chord <= " << std::setprecision(4) << e.prep.maxChordDeviation << " mm), "
      << e.result.files.size() << " file(s)"
      << (e.subPaths > 1 ? ", " + std::to_string(e.subPaths) + " sub-paths (one arc each)" : std::string())
      << ":";
  for (const auto& f : e.result.files) out << " " << f.filename().string();
  out << "\n";
  for (const auto& w : e.result.warnings) out << "warning: " << w << "\n";
}

}  // namespace spira::cli
