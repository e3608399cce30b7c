#include "spira/document/results.h"

#include "spira/document/document_state.h"
#include "spira/document/stage_report_codec.h"

namespace spira {

bool FieldResult::operator==(const FieldResult& o) const
{
  return kind == o.kind && source == o.source && values == o.values;
}

namespace {

template <class T>
bool sameReportValue(const std::shared_ptr<const T>& a, const std::shared_ptr<const T>& b)
{
  if (a == b) return true;
  return a && b && sameReport(*a, *b);
}

}  // namespace

bool StageReports::has(Stage s) const
{
  bool present = false;
  visitMember(s, [&](auto member) { present = (this->*member) != nullptr; });
  return present;
}

void StageReports::reset(Stage s)
{
  visitMember(s, [&](auto member) { (this->*member).reset(); });
}

bool StageReports::same(Stage s, const StageReports& o) const
{
  bool equal = true;
  visitMember(s, [&](auto member) { equal = sameReportValue(this->*member, o.*member); });
  return equal;
}

bool StageReports::identical(Stage s, const StageReports& o) const
{
  bool equal = true;
  visitMember(s, [&](auto member) { equal = this->*member == o.*member; });
  return equal;
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
    case Stage::Thermal:
      return thermal != nullptr;
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
  if (first <= stageIndex(Stage::Thermal)) thermal.reset();
  if (first <= stageIndex(Stage::Kinematics)) kinematics.reset();
  exported.reset();
  for (int i = first; i < kStageCount; ++i) reports.reset(stageAt(i));
}

void Results::setField(std::shared_ptr<const FieldResult> r, std::shared_ptr<const FieldStageReport> report)
{
  invalidateFrom(Stage::Field);
  field = std::move(r);
  reports.field = std::move(report);
}

void Results::setGeneratrices(std::shared_ptr<const Generatrices> r,
                              std::shared_ptr<const GeneratricesStageReport> report)
{
  invalidateFrom(Stage::Generatrices);
  generatrices = std::move(r);
  reports.generatrices = std::move(report);
}

void Results::setSpiral(std::shared_ptr<const Trajectory> r, std::shared_ptr<const SpiralStageReport> report)
{
  invalidateFrom(Stage::Spiral);
  spiral = std::move(r);
  reports.spiral = std::move(report);
}

void Results::setProcess(std::shared_ptr<const Trajectory> r,
                         std::shared_ptr<const ProcessStageReport> report)
{
  invalidateFrom(Stage::Process);
  process = std::move(r);
  reports.process = std::move(report);
}

void Results::setThermal(std::shared_ptr<const ThermalStageResult> r,
                         std::shared_ptr<const ThermalStageReport> report)
{
  invalidateFrom(Stage::Thermal);
  thermal = std::move(r);
  reports.thermal = std::move(report);
}

void Results::setKinematics(std::shared_ptr<const KinematicsResult> r,
                            std::shared_ptr<const KinematicsStageReport> report)
{
  invalidateFrom(Stage::Kinematics);
  kinematics = std::move(r);
  reports.kinematics = std::move(report);
}

void Results::setExport(std::shared_ptr<const ExportStageResult> r)
{
  invalidateFrom(Stage::Export);
  exported = std::move(r);
}

StageMask Results::differingStages(const Results& o) const
{
  const bool same[kStageCount] = {sameValue(field, o.field),
                                  sameValue(generatrices, o.generatrices),
                                  sameValue(spiral, o.spiral),
                                  sameValue(process, o.process),
                                  sameValue(thermal, o.thermal),
                                  sameValue(kinematics, o.kinematics),
                                  sameReportValue(exported, o.exported)};
  StageMask m = 0;
  for (int i = 0; i < kStageCount; ++i)
    if (!same[i] || !reports.same(stageAt(i), o.reports)) m |= stageBit(stageAt(i));
  return m;
}

}  // namespace spira
