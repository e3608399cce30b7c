#include "spira/document/results.h"

#include <nlohmann/json.hpp>

#include "spira/document/document_state.h"

namespace spira {

bool FieldResult::operator==(const FieldResult& o) const
{
  return kind == o.kind && source == o.source && values == o.values;
}

bool Results::has(Stage s) const
{
  switch (s) {
    case Stage::Field:
      return field != nullptr;
    case Stage::Generatrices:
      return generatrices != nullptr;
    case Stage::Spiral:
      return spiral != nullptr;
    case Stage::Process:
      return process != nullptr;
    case Stage::Kinematics:
      return kinematics != nullptr;
    case Stage::Export:
      return exported != nullptr;
  }
  return false;
}

StageMask Results::presentStages() const
{
  StageMask m = 0;
  for (int i = 0; i < kStageCount; ++i)
    if (has(stageAt(i))) m |= stageBit(stageAt(i));
  return m;
}

void Results::invalidateFrom(Stage s)
{
  const int first = stageIndex(s);
  if (first <= stageIndex(Stage::Field)) field.reset();
  if (first <= stageIndex(Stage::Generatrices)) generatrices.reset();
  if (first <= stageIndex(Stage::Spiral)) spiral.reset();
  if (first <= stageIndex(Stage::Process)) process.reset();
  if (first <= stageIndex(Stage::Kinematics)) kinematics.reset();
  exported.reset();
  for (int i = first; i < kStageCount; ++i) reports[i].reset();
}

void Results::setField(std::shared_ptr<const FieldResult> r)
{
  invalidateFrom(Stage::Field);
  field = std::move(r);
}

void Results::setGeneratrices(std::shared_ptr<const Generatrices> r)
{
  invalidateFrom(Stage::Generatrices);
  generatrices = std::move(r);
}

void Results::setSpiral(std::shared_ptr<const Trajectory> r)
{
  invalidateFrom(Stage::Spiral);
  spiral = std::move(r);
}

void Results::setProcess(std::shared_ptr<const Trajectory> r)
{
  invalidateFrom(Stage::Process);
  process = std::move(r);
}

void Results::setKinematics(std::shared_ptr<const KinematicsResult> r)
{
  invalidateFrom(Stage::Kinematics);
  kinematics = std::move(r);
}

void Results::setExport(std::shared_ptr<const nlohmann::json> r)
{
  invalidateFrom(Stage::Export);
  exported = std::move(r);
}

void Results::setReport(Stage s, std::shared_ptr<const nlohmann::json> report)
{
  reports[stageIndex(s)] = std::move(report);
}

StageMask Results::differingStages(const Results& o) const
{
  const bool same[kStageCount] = {
      sameValue(field, o.field),           sameValue(generatrices, o.generatrices),
      sameValue(spiral, o.spiral),         sameValue(process, o.process),
      sameValue(kinematics, o.kinematics), sameValue(exported, o.exported)};
  StageMask m = 0;
  for (int i = 0; i < kStageCount; ++i)
    if (!same[i] || !sameValue(reports[i], o.reports[i])) m |= stageBit(stageAt(i));
  return m;
}

}  // namespace spira
