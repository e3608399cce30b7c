#include "spira/pipeline/program_header.h"

#include <cstdlib>
#include <iomanip>
#include <sstream>

#include "spira/base/error.h"

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

std::time_t programTime()
{
  const char* epoch = std::getenv("SOURCE_DATE_EPOCH");
  if (!epoch || !*epoch) return std::time(nullptr);
  char* end = nullptr;
  const long long seconds = std::strtoll(epoch, &end, 10);
  if (*end != '\0' || seconds < 0)
    throw InputError(
        "SOURCE_DATE_EPOCH must be a whole number of seconds since 1970, not '" + std::string(epoch) + "'",
        "unset it to date programs now, or give e.g. SOURCE_DATE_EPOCH=0");
  return static_cast<std::time_t>(seconds);
}

}  // namespace spira
