#include "spira/document/invalidation.h"

#include <algorithm>
#include <variant>

#include "spira/io/json_codec.h"

namespace spira {

namespace {

// What an edit can touch, finer than the ChangeSet flags.
enum class Input {
  PartGeometry,     // mesh or source unit
  PartBoundary,     // lower-boundary choice: the field starts from it
  PartPlacement,    // T_world_part moved or turned about the vertical: the path lives in the part frame
  PartTilt,         // T_world_part's "up" changed: the part is planned with the world's up
  PartLabel,        // name or source path: only the program header shows them
  Substrate,        // where the part is built
  Decomposer,       // chosen decomposer id, or the values of its section
  ClosureFinder,    // chosen closure finder id, or the values of its section
  SpiralSection,    // "spiral" section
  ProcessSection,   // "process" section
  ThermalSection,   // "thermal" section: the optional thermal stage and its re-planning
  Cell,             // robot, tool, positioner, axes
  ExporterSection,  // "export.*" sections
  ImporterSection,  // "import.*"/"importer.*" sections: used at import time only
  InactiveSection,  // a decomposer or closure finder that is not the chosen one
  OtherSection,     // any other section: assume the worst
};

// The one table of staged invalidation: editing the input drops this stage and all later ones.
struct Rule {
  Input input;
  std::optional<Stage> from;
};
const Rule kInvalidation[] = {
    {Input::PartGeometry, Stage::Field},       {Input::PartBoundary, Stage::Field},
    {Input::PartPlacement, Stage::Kinematics}, {Input::PartTilt, Stage::Field},
    {Input::PartLabel, Stage::Export},         {Input::Substrate, Stage::Field},
    {Input::Decomposer, Stage::Generatrices},  {Input::ClosureFinder, Stage::Generatrices},
    {Input::SpiralSection, Stage::Spiral},     {Input::ProcessSection, Stage::Process},
    {Input::ThermalSection, Stage::Thermal},   {Input::Cell, Stage::Kinematics},
    {Input::ExporterSection, Stage::Export},   {Input::ImporterSection, std::nullopt},
    {Input::InactiveSection, std::nullopt},    {Input::OtherSection, Stage::Field},
};

std::optional<Stage> stageFor(Input input)
{
  for (const Rule& r : kInvalidation)
    if (r.input == input) return r.from;
  return Stage::Field;
}

bool startsWith(const std::string& s, const char* prefix)
{
  return s.rfind(prefix, 0) == 0;
}

// The thermal stage is optional: while it is off its values feed nothing.
bool thermalOn(const PlanSettings& s)
{
  const ParamSet values = s.section(PlanSettings::kThermalSection);
  if (!values.has("enabled")) return false;
  const bool* on = std::get_if<bool>(&values.values().at("enabled"));
  return on && *on;
}

Input classifySection(const std::string& section, const PlanSettings& before, const PlanSettings& after)
{
  if (section == PlanSettings::kProcessSection) return Input::ProcessSection;
  if (section == PlanSettings::kSpiralSection) return Input::SpiralSection;
  if (section == PlanSettings::kThermalSection)
    return thermalOn(before) || thermalOn(after) ? Input::ThermalSection : Input::InactiveSection;
  if (startsWith(section, "decomposer."))
    return section == before.decomposerId || section == after.decomposerId ? Input::Decomposer
                                                                           : Input::InactiveSection;
  if (startsWith(section, "closure."))
    return section == before.closureFinderId || section == after.closureFinderId ? Input::ClosureFinder
                                                                                 : Input::InactiveSection;
  if (startsWith(section, "export.")) return Input::ExporterSection;
  if (startsWith(section, "import.") || startsWith(section, "importer.")) return Input::ImporterSection;
  return Input::OtherSection;
}

std::vector<Input> changedInputs(const DocumentState& a, const DocumentState& b)
{
  std::vector<Input> inputs;
  if (a.part != b.part) {
    static const Part kNone;
    const Part& pa = a.part ? *a.part : kNone;
    const Part& pb = b.part ? *b.part : kNone;
    if (!a.part != !b.part || !sameValue(pa.mesh, pb.mesh) || pa.sourceUnit != pb.sourceUnit)
      inputs.push_back(Input::PartGeometry);
    if (pa.lowerBoundaryOverride != pb.lowerBoundaryOverride) inputs.push_back(Input::PartBoundary);
    if (!codec::sameTransform(pa.T_world_part, pb.T_world_part)) {
      // The world's up seen from the part: what the planner builds along.
      const Vec3 upA = pa.T_world_part.linear().transpose() * Vec3::UnitZ();
      const Vec3 upB = pb.T_world_part.linear().transpose() * Vec3::UnitZ();
      inputs.push_back((upA - upB).norm() > 1e-12 ? Input::PartTilt : Input::PartPlacement);
    }
    if (pa.name != pb.name || pa.sourcePath != pb.sourcePath) inputs.push_back(Input::PartLabel);
  }
  if (!sameValue(a.substrate, b.substrate)) inputs.push_back(Input::Substrate);
  if (!sameValue(a.cell, b.cell)) inputs.push_back(Input::Cell);
  if (a.settings != b.settings) {
    static const PlanSettings kDefaults;
    const PlanSettings& sa = a.settings ? *a.settings : kDefaults;
    const PlanSettings& sb = b.settings ? *b.settings : kDefaults;
    if (sa.decomposerId != sb.decomposerId) inputs.push_back(Input::Decomposer);
    if (sa.closureFinderId != sb.closureFinderId) inputs.push_back(Input::ClosureFinder);
    for (const auto& [section, values] : sa.params)
      if (sb.section(section) != values) inputs.push_back(classifySection(section, sa, sb));
    for (const auto& [section, values] : sb.params)
      if (!sa.params.count(section) && !values.values().empty())
        inputs.push_back(classifySection(section, sa, sb));
  }
  return inputs;
}

std::set<std::string> changedSections(const PlanSettings& a, const PlanSettings& b)
{
  std::set<std::string> out;
  for (const auto& [section, values] : a.params)
    if (b.section(section) != values) out.insert(section);
  for (const auto& [section, values] : b.params)
    if (a.section(section) != values) out.insert(section);
  return out;
}

}  // namespace

ChangeSet diffStates(const DocumentState& before, const DocumentState& after)
{
  ChangeSet cs;
  if (!sameValue(before.part, after.part)) cs.add(Change::Part);
  if (!sameValue(before.substrate, after.substrate)) cs.add(Change::Substrate);
  if (!sameValue(before.cell, after.cell)) cs.add(Change::Cell);
  if (!sameValue(before.scan, after.scan)) cs.add(Change::Scan);
  if (!sameValue(before.settings, after.settings)) {
    cs.add(Change::Settings);
    static const PlanSettings kDefaults;
    const PlanSettings& sa = before.settings ? *before.settings : kDefaults;
    const PlanSettings& sb = after.settings ? *after.settings : kDefaults;
    cs.sections = changedSections(sa, sb);
    cs.strategyChanged = sa.decomposerId != sb.decomposerId || sa.closureFinderId != sb.closureFinderId;
  }
  cs.stages = before.results.differingStages(after.results);
  if (cs.stages) cs.add(Change::Results);
  return cs;
}

std::optional<Stage> firstInvalidatedStage(const DocumentState& before, const DocumentState& after)
{
  std::optional<Stage> first;
  for (Input input : changedInputs(before, after)) {
    const auto s = stageFor(input);
    if (s && (!first || stageIndex(*s) < stageIndex(*first))) first = s;
  }
  return first;
}

}  // namespace spira
