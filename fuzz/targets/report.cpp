// A plan folder's report.json, as export reads it for the program header and the plan's verdict.
#include "../fuzz_support.h"
#include "spira/document/plan_report.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  return spira::fuzz::refusalsAllowed([&] {
    const nlohmann::json report =
        spira::parsePlanReport(std::string(spira::fuzz::bytes(data, size)), "report.json");
    spira::summarisePlanReport(report, "report.json");
  });
}
