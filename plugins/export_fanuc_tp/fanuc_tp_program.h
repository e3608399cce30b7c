#pragma once

#include <string>
#include <vector>

#include "spira/base/output_set.h"
#include "spira/base/progress.h"
#include "spira/export/export_path.h"

namespace spira {

// How the speed of each move is written: mm/sec or cm/min rounded to whole units (the TP
// accepts integers), or the move's planned duration in msec.
enum class TpSpeedUnit { MmPerSec, CmPerMin, Msec };

// What the TP writer needs besides the path; every value already checked against the schema.
struct TpSettings {
  std::string programName;                       // wanted name; sanitised by the writer
  size_t maxPoints = 9000;                       // positions per program
  int uframe = 0;                                // UFRAME_NUM
  int utool = 1;                                 // UTOOL_NUM
  bool jointPositions = false;                   // path points as J1..J6 instead of XYZWPR
  std::string defaultConfig = "N U T, 0, 0, 0";  // CONFIG when the cell gives none
  int cnt = 100;                                 // CNT value of the path moves
  TpSpeedUnit speedUnit = TpSpeedUnit::MmPerSec;
  double approachSpeed = 20.0;  // mm/s
  int jointSpeed = 20;          // % of the first (joint) move
  ProcessCommand process = ProcessCommand::Speed;
  int weldSchedule = 1;  // Arc Start[weldSchedule]
  int endSchedule = 1;   // Arc End[endSchedule]
  int wfsOutput = 1;     // AO[wfsOutput]
  double wfsOffset = 0.0;
  double wfsGain = 100.0;  // counts per m/min
  std::string date;        // header "date" ("YYYY-MM-DD[ HH:MM[:SS]]"), for /ATTR CREATE
};

struct TpOutput {
  std::vector<OutputFile> files;
  double worstSpeedError = 0.0;   // largest relative error of a rounded path speed
  double worstSpeedWanted = 0.0;  // the planned speed of that move, mm/s
  size_t worstSpeedMove = 0;      // its index in the export path
};

// Writes NAME.ls (or, past maxPoints, a main program that CALLs numbered parts in order) with
// CRLF line endings. `header` is the comment block the programs open with.
TpOutput writeTpProgram(const ExportPath& path, const TpSettings& settings,
                        const std::vector<std::string>& header, Progress& progress);

// The program name the writer will use for `wanted` (TP rules: capitals, at most 36 characters).
std::string tpProgramName(const std::string& wanted);

}  // namespace spira
