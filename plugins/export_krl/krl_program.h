#pragma once

#include <string>
#include <vector>

#include "spira/base/progress.h"
#include "spira/export/export_path.h"
#include "spira/base/output_set.h"

namespace spira {

// What the KRL writer needs besides the path; every value already checked against the schema.
struct KrlSettings {
  std::string programName;      // wanted name; sanitised by the writer
  size_t maxPoints = 5000;      // positions per .dat
  int tool = 1;                 // TOOL_DATA[tool]
  int base = 0;                 // BASE_DATA[base]; 0 = $NULLFRAME
  double cdis = 0.5;            // mm, $APO.CDIS; 0 = exact stop at every point
  int jointSpeed = 20;          // %, BAS(#VEL_PTP) of the first (PTP) move
  double approachSpeed = 20.0;  // mm/s
  ProcessCommand process = ProcessCommand::Speed;
  int arcOutput = 1;  // $OUT[arcOutput] is the arc-on signal
  int weldJob = 1;    // job number written to the job outputs at the start
  int endJob = 0;     // job selected where the arc is put out; 0 = keep the weld job
  int jobOutput = 0;  // first of the job outputs; 0 = do not write a job
  int jobBits = 8;    // width of the job number
  int wfsOutput = 1;  // $ANOUT[wfsOutput] carries the wire feed
  double wfsOffset = 0.0;
  double wfsGain = 0.1;  // per m/min
};

// Writes the .src/.dat pair (or, past maxPoints, a main pair that calls numbered part pairs in
// order). `header` is the comment block the programs open with. Throws InputError when an
// analog value leaves KRL's $ANOUT range [-1, 1].
std::vector<OutputFile> writeKrlProgram(const ExportPath& path, const KrlSettings& settings,
                                        const std::vector<std::string>& header, Progress& progress);

// The program name the writer will use for `wanted` (KRL identifier rules).
std::string krlProgramName(const std::string& wanted);

}  // namespace spira
