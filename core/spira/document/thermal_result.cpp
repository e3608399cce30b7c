#include "spira/document/thermal_result.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <nlohmann/json.hpp>

#include "spira/base/error.h"
#include "spira/document/trajectory_codec.h"
#include "spira/io/json_codec.h"

namespace spira {

namespace {

// Bit for bit, so that NaN (a point with nothing below it) equals NaN.
bool sameDoubles(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

const char* kDamaged = "the project file is damaged";

}  // namespace

float ThermalFrameSet::at(size_t frame, size_t node) const
{
  const auto& v = values[frame];
  if (node >= v.size() || v[node] == kNotDeposited) return std::numeric_limits<float>::quiet_NaN();
  return static_cast<float>(offset + step * v[node]);
}

size_t ThermalFrameSet::frameAt(double t) const
{
  const auto it = std::upper_bound(times.begin(), times.end(), t);
  return it == times.begin() ? 0 : static_cast<size_t>(it - times.begin()) - 1;
}

ThermalFrameSet ThermalFrameSet::quantise(std::vector<double> times,
                                          const std::vector<std::vector<float>>& frames)
{
  ThermalFrameSet out;
  out.times = std::move(times);
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (const auto& f : frames)
    for (float v : f)
      if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (lo > hi) lo = hi = 0.0f;
  out.offset = lo;
  out.step = hi > lo ? (static_cast<double>(hi) - lo) / (kNotDeposited - 1) : 1.0;
  out.values.reserve(frames.size());
  for (const auto& f : frames) {
    size_t n = f.size();
    while (n > 0 && !std::isfinite(f[n - 1])) --n;
    std::vector<std::uint16_t> q(n);
    for (size_t i = 0; i < n; ++i)
      q[i] = std::isfinite(f[i]) ? static_cast<std::uint16_t>(std::lround((f[i] - out.offset) / out.step))
                                 : kNotDeposited;
    out.values.push_back(std::move(q));
  }
  return out;
}

bool ThermalFrameSet::operator==(const ThermalFrameSet& o) const
{
  return sameDoubles(times, o.times) && values == o.values && offset == o.offset && step == o.step;
}

std::vector<std::array<double, 2>> ThermalStageResult::historyAt(size_t node) const
{
  std::vector<std::array<double, 2>> out;
  for (size_t f = 0; f < frames.size(); ++f)
    if (const float v = frames.at(f, node); std::isfinite(v)) out.push_back({frames.times[f], v});
  return out;
}

bool ThermalStageResult::operator==(const ThermalStageResult& o) const
{
  if (probeTemperatures.size() != o.probeTemperatures.size()) return false;
  for (size_t k = 0; k < probeTemperatures.size(); ++k)
    if (!sameDoubles(probeTemperatures[k], o.probeTemperatures[k])) return false;
  const bool sameReplan =
      replanned == o.replanned || (replanned && o.replanned && *replanned == *o.replanned);
  return nodes == o.nodes && triangles == o.triangles && pointNode == o.pointNode &&
         sameDoubles(peak, o.peak) && sameDoubles(interpass, o.interpass) &&
         sameDoubles(timeAboveMelt, o.timeAboveMelt) && sameDoubles(poolLength, o.poolLength) &&
         sameDoubles(bond, o.bond) && risk == o.risk && sameDoubles(nodePeak, o.nodePeak) &&
         probeNodes == o.probeNodes && sameDoubles(probeTimes, o.probeTimes) && frames == o.frames &&
         sameReplan;
}

namespace {

nlohmann::json::binary_t u16Blob(const std::vector<std::uint16_t>& v)
{
  std::vector<std::uint8_t> out;
  out.reserve(2 * v.size());
  for (std::uint16_t x : v)
    out.insert(out.end(), {static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(x >> 8)});
  return nlohmann::json::binary_t(std::move(out));
}

std::vector<std::uint16_t> u16FromBlob(const nlohmann::json& j, const std::string& what)
{
  if (!j.is_binary() || j.get_binary().size() % 2 != 0)
    throw InputError(what + ": expected a binary array of 16-bit values", kDamaged);
  const auto& b = j.get_binary();
  std::vector<std::uint16_t> v(b.size() / 2);
  for (size_t i = 0; i < v.size(); ++i) v[i] = static_cast<std::uint16_t>(b[2 * i] | (b[2 * i + 1] << 8));
  return v;
}

nlohmann::json::binary_t bytesBlob(const std::vector<std::uint8_t>& v)
{
  return nlohmann::json::binary_t(std::vector<std::uint8_t>(v));
}

std::vector<std::int32_t> flatTriangles(const std::vector<std::array<std::int32_t, 3>>& t)
{
  std::vector<std::int32_t> out;
  out.reserve(3 * t.size());
  for (const auto& tri : t) out.insert(out.end(), tri.begin(), tri.end());
  return out;
}

template <class T>
std::vector<T> sized(std::vector<T> v, size_t n, const std::string& what)
{
  if (v.size() != n)
    throw InputError(
        what + ": " + std::to_string(v.size()) + " values where " + std::to_string(n) + " belong", kDamaged);
  return v;
}

}  // namespace

nlohmann::json thermalResultToJson(const ThermalStageResult& r)
{
  nlohmann::json probes = nlohmann::json::array();
  for (const auto& p : r.probeTemperatures) probes.push_back(codec::doublesToBlob(p));
  nlohmann::json frameValues = nlohmann::json::array();
  for (const auto& f : r.frames.values) frameValues.push_back(u16Blob(f));
  return {{"nodes", codec::vec3sToBlob(r.nodes)},
          {"triangles", codec::intsToBlob(flatTriangles(r.triangles))},
          {"points", r.pointCount()},
          {"point_node", codec::intsToBlob(r.pointNode)},
          {"peak", codec::doublesToBlob(r.peak)},
          {"interpass", codec::doublesToBlob(r.interpass)},
          {"time_above_melt", codec::doublesToBlob(r.timeAboveMelt)},
          {"pool_length", codec::doublesToBlob(r.poolLength)},
          {"bond", codec::doublesToBlob(r.bond)},
          {"risk", bytesBlob(r.risk)},
          {"node_peak", codec::doublesToBlob(r.nodePeak)},
          {"probe_nodes", codec::intsToBlob(r.probeNodes)},
          {"probe_times", codec::doublesToBlob(r.probeTimes)},
          {"probe_temperatures", std::move(probes)},
          {"frames",
           {{"times", codec::doublesToBlob(r.frames.times)},
            {"offset", r.frames.offset},
            {"step", r.frames.step},
            {"values", std::move(frameValues)}}},
          {"replanned", r.replanned ? trajectoryToJson(*r.replanned) : nlohmann::json(nullptr)}};
}

ThermalStageResult thermalResultFromJson(const nlohmann::json& j, const std::string& what)
{
  ThermalStageResult r;
  const auto key = [&](const char* k) -> const nlohmann::json& { return codec::field(j, k, what); };
  const auto doubles = [&](const char* k, size_t n) {
    return sized(codec::decodeDoubleBlob(key(k), what + " " + k), n, what + " " + k);
  };
  r.nodes = codec::blobToVec3s(key("nodes"), what + " nodes");
  const auto flat = codec::blobToInts(key("triangles"), what + " triangles");
  if (flat.size() % 3 != 0) throw InputError(what + ": a triangle lacks a corner", kDamaged);
  for (size_t i = 0; i < flat.size(); i += 3) {
    for (size_t c = 0; c < 3; ++c)
      if (flat[i + c] < 0 || static_cast<size_t>(flat[i + c]) >= r.nodes.size())
        throw InputError(what + ": a triangle names a node that does not exist", kDamaged);
    r.triangles.push_back({flat[i], flat[i + 1], flat[i + 2]});
  }
  const std::int64_t count = codec::intField(j, "points", what);
  if (count < 0) throw InputError(what + ": negative point count", kDamaged);
  const auto n = static_cast<size_t>(count);
  r.pointNode = sized(codec::blobToInts(key("point_node"), what + " point_node"), n, what + " point_node");
  for (std::int32_t node : r.pointNode)
    if (node < 0 || static_cast<size_t>(node) >= r.nodes.size())
      throw InputError(what + ": a point's node does not exist", kDamaged);
  r.peak = doubles("peak", n);
  r.interpass = doubles("interpass", n);
  r.timeAboveMelt = doubles("time_above_melt", n);
  r.poolLength = doubles("pool_length", n);
  r.bond = doubles("bond", n);
  const auto& risk = key("risk");
  if (!risk.is_binary()) throw InputError(what + ": 'risk' is not a binary array", kDamaged);
  r.risk =
      sized(std::vector<std::uint8_t>(risk.get_binary().begin(), risk.get_binary().end()), n, what + " risk");
  r.nodePeak = doubles("node_peak", r.nodes.size());
  r.probeNodes = codec::blobToInts(key("probe_nodes"), what + " probe_nodes");
  r.probeTimes = codec::decodeDoubleBlob(key("probe_times"), what + " probe_times");
  const auto& probes = key("probe_temperatures");
  if (!probes.is_array() || probes.size() != r.probeNodes.size())
    throw InputError(what + ": one probe history per probe node expected", kDamaged);
  for (const auto& p : probes)
    r.probeTemperatures.push_back(
        sized(codec::decodeDoubleBlob(p, what + " probe"), r.probeTimes.size(), what));
  const auto& frames = key("frames");
  const std::string fw = what + " frames";
  r.frames.times = codec::decodeDoubleBlob(codec::field(frames, "times", fw), fw + " times");
  r.frames.offset = codec::numberField(frames, "offset", fw);
  r.frames.step = codec::numberField(frames, "step", fw);
  const auto& values = codec::field(frames, "values", fw);
  if (!values.is_array() || values.size() != r.frames.times.size())
    throw InputError(fw + ": one frame per time expected", kDamaged);
  for (const auto& f : values) {
    r.frames.values.push_back(u16FromBlob(f, fw));
    if (r.frames.values.back().size() > r.nodes.size())
      throw InputError(fw + ": a frame has too many nodes", kDamaged);
  }
  if (const auto& t = key("replanned"); !t.is_null())
    r.replanned = std::make_shared<const Trajectory>(trajectoryFromJson(t, what + " replanned"));
  return r;
}

}  // namespace spira
