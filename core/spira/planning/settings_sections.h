#pragma once

#include <vector>

#include "spira/plugin/settings_section.h"

namespace spira {

// The planner's own settings sections, by name and schema (plan_schemas.h reads them).
const SettingsSection& spiralSection();
const SettingsSection& processSection();

// Every section the planner reads, in the order panels and CLI help list them.
const std::vector<SettingsSection>& planSections();

}  // namespace spira
