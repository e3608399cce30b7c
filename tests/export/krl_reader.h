#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "spira/base/transform.h"

// A reader for the KRL that export.krl writes, independent of the writer: it parses the .dat
// targets and walks the .src statements in execution order (following part calls), so tests can
// compare what a controller would run with the plan.
namespace spira::test {

struct KrlTarget {
  Vec3 xyz = Vec3::Zero();
  double a = 0.0, b = 0.0, c = 0.0;  // degrees
  std::optional<int> s, t;
  std::optional<double> e1, e2;
};

struct KrlMove {
  std::string program;  // program the move is in
  std::string motion;   // "PTP" or "LIN"
  std::string target;   // "XP12", "XAPPROACH", ...
  KrlTarget pose;
  bool approximated = false;          // C_DIS
  double velCp = 0.0;                 // m/s in force for the move (0 before any $VEL.CP)
  std::vector<std::string> triggers;  // TRIGGER statements planned with this move
  std::vector<std::string> comments;  // comment lines since the previous move
};

struct KrlRun {
  std::vector<KrlMove> moves;
  std::vector<std::string> programs;    // in the order they ran
  std::vector<std::string> problems;    // format violations found while reading
  std::vector<std::string> statements;  // every non-comment statement of the main program
  std::vector<size_t> waitAfter;        // index into moves of the move each WAIT SEC follows
  std::vector<double> waitSeconds;      // and its time, s
};

// Reads "<dir>/<name>.dat": every DECL E6POS.
std::map<std::string, KrlTarget> readKrlDat(const std::filesystem::path& file,
                                            std::vector<std::string>& problems);

// Runs "<dir>/<mainName>.src" as far as motion and triggers go.
KrlRun runKrl(const std::filesystem::path& dir, const std::string& mainName);

// The pose of a target (KUKA A, B, C) as a transform.
Transform krlPose(const KrlTarget& t);

}  // namespace spira::test
