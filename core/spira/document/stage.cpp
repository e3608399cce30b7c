#include "spira/document/stage.h"

#include "spira/document/change_set.h"

namespace spira {

const char* stageName(Stage s)
{
  switch (s) {
    case Stage::Field:
      return "field";
    case Stage::Generatrices:
      return "generatrices";
    case Stage::Spiral:
      return "spiral";
    case Stage::Process:
      return "process";
    case Stage::Thermal:
      return "thermal";
    case Stage::Kinematics:
      return "kinematics";
    case Stage::Export:
      return "export";
  }
  return "unknown";
}

std::optional<Stage> parseStageName(std::string_view name)
{
  for (int i = 0; i < kStageCount; ++i)
    if (name == stageName(stageAt(i))) return stageAt(i);
  return std::nullopt;
}

ChangeSet& ChangeSet::operator|=(const ChangeSet& o)
{
  flags |= o.flags;
  stages |= o.stages;
  sections.insert(o.sections.begin(), o.sections.end());
  strategyChanged = strategyChanged || o.strategyChanged;
  return *this;
}

}  // namespace spira
