#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "spira/base/transform.h"

// A reader for the FANUC .ls that export.fanuc_tp writes, independent of the writer: it checks
// the file layout (CRLF, LINE_COUNT, line numbering) and walks /MN in execution order, following
// CALLs into the part programs.
namespace spira::test {

struct TpPosition {
  bool joint = false;
  int uf = -1, ut = -1;
  std::string config;
  Vec3 xyz = Vec3::Zero();
  double w = 0.0, p = 0.0, r = 0.0;  // degrees
  std::array<double, 6> j{};         // degrees
  bool gp2 = false;
  std::array<double, 2> e{};  // GP2 J1, J2
};

struct TpLine {
  int number = 0;
  char type = ' ';   // 'L', 'J' for motion, ' ' otherwise
  std::string body;  // without the number, the type and the closing " ;"
};

struct TpFile {
  std::string progName;
  std::map<std::string, std::string> attributes;  // /ATTR key = value (without the ';')
  std::vector<TpLine> lines;
  std::map<int, TpPosition> positions;
  std::vector<std::string> problems;
};

struct TpMove {
  std::string program;
  char type = 'L';
  int index = 0;  // P[index] in its program
  TpPosition pos;
  std::string speed;        // "6mm/sec", "36cm/min", "500msec", "20%"
  std::string termination;  // "FINE" or "CNT100"
  std::string options;      // the rest, e.g. "TA 0.00sec,AO[1]=410"
  std::vector<std::string> comments;
};

struct TpRun {
  std::vector<TpMove> moves;
  std::vector<std::string> programs;
  std::vector<std::string> problems;
  std::vector<std::string> statements;  // non-motion statements of every program, in run order
  std::vector<size_t> arcStartAfter;    // index into moves of the move each Arc Start follows
  std::vector<size_t> arcEndAfter;
  std::vector<size_t> waitAfter;    // index into moves of the move each WAIT t(sec) follows
  std::vector<double> waitSeconds;  // and its time, s
};

TpFile readTpFile(const std::filesystem::path& file);
TpRun runTp(const std::filesystem::path& dir, const std::string& mainName);

// The pose of a Cartesian position (FANUC W, P, R) as a transform.
Transform tpPose(const TpPosition& p);

}  // namespace spira::test
