#pragma once

#include <cstddef>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "spira/base/transform.h"

namespace spira {

// A scan compared with the part: the file it was read from and where its alignment put it. The points
// are not kept in the project (a million-point scan would make every save slow): they are read again
// from `file` and moved by `T_part_scan`, so the comparison comes back as it was without a new fit.
struct ScanRecord {
  std::string file;                               // as given; the project also keeps it relative
  Transform T_part_scan = Transform::Identity();  // scan coordinates into the part's frame
  double rmsMm = 0.0;                             // the fit's residual, mm
  std::size_t depositedTo = 0;  // plan points laid when it was taken (0: not a scan of a build under way)

  bool operator==(const ScanRecord& o) const;
  bool operator!=(const ScanRecord& o) const { return !(*this == o); }
};

nlohmann::json scanRecordToJson(const ScanRecord& s);
ScanRecord scanRecordFromJson(const nlohmann::json& j);  // throws InputError

}  // namespace spira
