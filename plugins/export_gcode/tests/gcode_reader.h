#pragma once

#include <map>
#include <string>
#include <vector>

// An independent reader of the G-code the exporter writes, as a controller would run it: modal axis
// words and F, the process lines matched against the machine file's strings.
namespace spira::test {

struct GcodeMove {
  bool rapid = false;
  std::map<char, double> axes;  // every axis word in force after the block (modal)
  double feed = 0.0;            // mm/min in force (0 for a rapid)
  bool arcOn = false;           // the arc burns during this move
  double wireFeed = -1.0;       // the last wire-feed value written before it (-1: none yet)
};

struct GcodeRun {
  std::vector<GcodeMove> moves;
  std::vector<std::string> events;  // "move", "arc on", "arc off", "wire feed", "dwell" in program order
  std::vector<double> wireFeeds;    // each wire-feed value written
  std::vector<double> dwells;       // each G4 wait, s
  std::vector<std::string> problems;
};

// `wireFeedPrefix` is the machine's wire_feed up to {wfs}, `dwellPrefix` its dwell up to {s}.
GcodeRun readGcode(const std::string& text, const std::string& arcOn, const std::string& arcOff,
                   const std::string& wireFeedPrefix, const std::string& dwellPrefix);

}  // namespace spira::test
