#pragma once

#include <string>
#include <vector>

#include "spira/base/output_set.h"
#include "spira/thermal/thermal_study.h"

namespace spira {

// The temperature field over the build as a ParaView time series: `<stem>.pvd` listing one
// `<stem>_NNNN.vtu` per frame (the shell's triangles, mm; point data "temperature_C", NaN where
// not yet deposited; cell data "deposited", 0/1 by the frame's time, to hide the unborn deposit
// with a Threshold). Inline base64, uncompressed: read without a compression library.
std::vector<OutputFile> thermalTimeSeries(const ThermalStudy& study, const std::string& stem);

}  // namespace spira
