#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace spira {

// The recompute stages, in pipeline order. A stage's result depends on the inputs and on every
// earlier stage, so dropping one stage drops all later ones (PrusaSlicer's PrintBase model).
enum class Stage { Field, Generatrices, Spiral, Process, Kinematics, Export };
constexpr int kStageCount = 6;

// Stable snake_case names, used in the project file and in reports: "field", "generatrices",
// "spiral", "process", "kinematics", "export".
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
