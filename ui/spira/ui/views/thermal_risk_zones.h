#pragma once

#include <cstddef>
#include <vector>

class QListWidget;

namespace spira {
struct Results;
struct ThermalStageResult;
}  // namespace spira

namespace spira::ui {

class LogPanel;

// A run of collapse-risk points along the path (gaps of a few safe points do not split it).
struct RiskZone {
  size_t first = 0, last = 0;  // point indices, inclusive
  size_t points = 0;           // at risk inside it
  size_t worst = 0;            // the point with the highest Bond number
};
std::vector<RiskZone> thermalRiskZones(const ThermalStageResult& thermal);

// Lists in the messages panel the thermal stage's collapse-risk zones (at most `maxZones`, with a
// count of the rest) and the points over the interpass limit; each message carries its zone's
// worst point in `pointRole`, so a click selects it (and charts its temperature).
void listThermalRiskZones(LogPanel& log, QListWidget& list, const Results& results, int pointRole,
                          int maxZones);

}  // namespace spira::ui
