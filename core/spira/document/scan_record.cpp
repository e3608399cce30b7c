#include "spira/document/scan_record.h"

#include <nlohmann/json.hpp>

#include "spira/base/error.h"
#include "spira/io/json_codec.h"

namespace spira {

bool ScanRecord::operator==(const ScanRecord& o) const
{
  return file == o.file && codec::sameTransform(T_part_scan, o.T_part_scan) && rmsMm == o.rmsMm &&
         depositedTo == o.depositedTo;
}

nlohmann::json scanRecordToJson(const ScanRecord& s)
{
  return {{"file", s.file},
          {"T_part_scan", codec::transformToJson(s.T_part_scan)},
          {"rms_mm", s.rmsMm},
          {"deposited_to", s.depositedTo}};
}

ScanRecord scanRecordFromJson(const nlohmann::json& j)
{
  const std::string what = "project scan";
  if (!j.is_object())
    throw InputError("the project's scan is not an object", "save the project again in Spira");
  ScanRecord s;
  s.file = codec::stringField(j, "file", what);
  s.T_part_scan = codec::transformFromJson(codec::field(j, "T_part_scan", what), what);
  s.rmsMm = codec::numberField(j, "rms_mm", what);
  const std::int64_t at = codec::intField(j, "deposited_to", what);
  if (at < 0)
    throw InputError("the project's scan has deposited_to " + std::to_string(at),
                     "save the project again in Spira");
  s.depositedTo = std::size_t(at);
  return s;
}

}  // namespace spira
