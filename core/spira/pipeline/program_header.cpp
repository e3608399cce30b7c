#include "spira/pipeline/program_header.h"

#include <iomanip>
#include <sstream>

namespace spira {

std::map<std::string, std::string> programHeader(const std::string& part, const std::string& cell,
                                                 const PlanReportSummary& plan, std::time_t when)
{
  std::map<std::string, std::string> h;
  h["part"] = part;
  h["cell"] = cell.empty() ? "none (targets in the part frame)" : cell;
  std::ostringstream date;
  date << std::put_time(std::gmtime(&when), "%Y-%m-%d %H:%M UTC");
  h["date"] = date.str();
  std::ostringstream line;
  line << std::setprecision(4) << plan.partType << " part, " << plan.revolutions << " revolutions, deposit "
       << plan.heightMin << " .. " << plan.heightMax << " mm, path " << plan.pathLength << " mm";
  h["plan"] = line.str();
  return h;
}

}  // namespace spira
