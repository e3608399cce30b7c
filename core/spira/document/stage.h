#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace spira {

// The recompute stages, in pipeline order. A stage's result depends on the inputs and on every
// earlier stage, so dropping one stage drops all later ones (PrusaSlicer's PrintBase model). The
// thermal stage is optional (off unless the "thermal" section enables it): absent, the later
// stages work on the process stage's path as they would without it.
enum class Stage { Field, Generatrices, Spiral, Process, Thermal, Kinematics, Export };
constexpr int kStageCount = 7;

// Stable snake_case names, used in the project file and in reports: "field", "generatrices",
// "spiral", "process", "thermal", "kinematics", "export".
const char* stageName(Stage s);
std::optional<Stage> parseStageName(std::string_view name);

constexpr int stageIndex(Stage s)
{
  return static_cast<int>(s);
}
constexpr Stage stageAt(int index)
{
  return static_cast<Stage>(index);
}

// A set of stages as bits (bit i = stage i).
using StageMask = std::uint32_t;
constexpr StageMask stageBit(Stage s)
{
  return StageMask{1} << stageIndex(s);
}
constexpr StageMask kAllStages = (StageMask{1} << kStageCount) - 1;
// `s` and every later stage.
constexpr StageMask stagesFrom(Stage s)
{
  return kAllStages & ~(stageBit(s) - 1);
}

}  // namespace spira
