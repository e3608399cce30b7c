#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "spira/base/transform.h"

// An independent reader of the RAPID the exporter writes, for the tests: it knows RAPID's data
// syntax (nested [..] aggregates), not the writer's code. It runs PROC main of a module, following
// procedure calls into the other .mod files of the folder, and lists the moves in execution order.
namespace spira::test {

// A RAPID aggregate value: a number, a string or a list of values.
struct RapidValue {
  double number = 0.0;
  std::string text;
  bool isText = false;
  std::vector<RapidValue> items;
  bool isList = false;

  const RapidValue& operator[](size_t i) const { return items.at(i); }
};

struct RapidData {
  std::string storage;  // PERS, CONST, VAR
  std::string type;     // robtarget, tooldata...
  RapidValue value;
};

struct RapidMove {
  std::string instruction;        // MoveJ, MoveL, ArcLStart, ArcL, ArcLEnd, WaitTime
  std::vector<std::string> args;  // the comma-separated arguments, trimmed ("p12", "v10", "fine"...)
  std::string tool, wobj;         // the tool argument and \WObj
  double wait = 0.0;              // WaitTime's seconds
};

struct RapidRun {
  std::map<std::string, RapidData> data;  // every declaration of every module, by name
  std::vector<std::string> modules;       // MODULE names in the order read
  std::vector<RapidMove> moves;
  std::vector<std::string> problems;  // syntax the reader did not accept
};

RapidValue parseRapidValue(const std::string& text);
RapidRun runRapid(const std::filesystem::path& dir, const std::string& mainModule);

// [[x,y,z],[q1,q2,q3,q4]...] as a transform, the quaternion turned into the full rotation matrix
// by its textbook formula (normalised first).
Transform rapidPose(const RapidValue& target);

}  // namespace spira::test
