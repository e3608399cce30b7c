#pragma once

class QListWidget;

namespace spira {
struct Results;
}

namespace spira::ui {

class LogPanel;

// Lists in the messages panel the points a plan got wrong: deposit heights outside the process
// window, then (with a solved motion) points the robot cannot reach, points beyond an axis limit
// and collisions left unresolved. Each message carries its point index in `pointRole`, so a click
// selects the point; at most `maxPerKind` are listed per kind, with a count of the rest.
void listOffendingPoints(LogPanel& log, QListWidget& list, const Results& results, int pointRole,
                         int maxPerKind);

}  // namespace spira::ui
