#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "spira/base/transform.h"
#include "spira/path/trajectory.h"

namespace spira {

// Snapshots of the temperature field over the build, quantised to 16 bits between `offset` and
// offset + 65534 x step (about 0.05 C over the range of a steel build): a frame is for looking at,
// and the dome's 200 frames stay a few megabytes in the project. Nodes are numbered in the order
// the torch lays them, so a frame stores only the prefix up to its last deposited node.
struct ThermalFrameSet {
  static constexpr std::uint16_t kNotDeposited = 0xFFFF;
  std::vector<double> times;                       // s
  std::vector<std::vector<std::uint16_t>> values;  // [frame][node], prefix; kNotDeposited where unborn
  double offset = 0.0, step = 1.0;                 // C
  bool empty() const { return times.empty(); }
  size_t size() const { return times.size(); }
  // C at `node` in frame `frame`; NaN where not deposited yet.
  float at(size_t frame, size_t node) const;
  // The frame at or before time t (s); 0 when t precedes the first.
  size_t frameAt(double t) const;
  // Quantises `frames` ([frame][node], C, NaN where not deposited).
  static ThermalFrameSet quantise(std::vector<double> times, const std::vector<std::vector<float>>& frames);

  bool operator==(const ThermalFrameSet& o) const;
  bool operator!=(const ThermalFrameSet& o) const { return !(*this == o); }
};

// The thermal stage of a plan (pipeline/thermal_stage.h): what the views draw and the report lists,
// per trajectory point and per shell node, in the part frame. Immutable once made; the document
// holds it by shared pointer. Its summary is the stage's report (StageReports::thermal).
struct ThermalStageResult {
  // The shell the field lives on: nodes (mm) and triangles, for drawing the part by temperature.
  std::vector<Vec3> nodes;
  std::vector<std::array<std::int32_t, 3>> triangles;
  // Per trajectory point of the simulated path: its node, peak and interpass temperature (C), time
  // above melting (s), melt-pool length (mm), weighted Bond number and collapse-risk flag.
  std::vector<std::int32_t> pointNode;
  std::vector<double> peak, interpass, timeAboveMelt, poolLength, bond;
  std::vector<std::uint8_t> risk;
  // Per node: the highest temperature reached (C).
  std::vector<double> nodePeak;
  // Histories at the probe nodes: [probe][time], C.
  std::vector<std::int32_t> probeNodes;
  std::vector<double> probeTimes;
  std::vector<std::vector<double>> probeTemperatures;
  ThermalFrameSet frames;
  // The re-planned path that meets the interpass limit, when re-planning changed it; null: the
  // process stage's path was simulated and is what the later stages use.
  std::shared_ptr<const Trajectory> replanned;

  size_t pointCount() const { return peak.size(); }
  // Temperature against time at `node` from the frames (s, C), skipping frames before its birth.
  std::vector<std::array<double, 2>> historyAt(size_t node) const;

  bool operator==(const ThermalStageResult& o) const;
  bool operator!=(const ThermalStageResult& o) const { return !(*this == o); }
};

// Project-file codec (results_codec.cpp stores it under "thermal"); binary blobs, bit for bit.
nlohmann::json thermalResultToJson(const ThermalStageResult& r);
ThermalStageResult thermalResultFromJson(const nlohmann::json& j, const std::string& what);  // InputError

}  // namespace spira
