#include "spira/pipeline/comparison_reader.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/io/json_read.h"

namespace spira {

namespace {

namespace fs = std::filesystem;

constexpr const char* kJsonHint = "give the compare.json written by spira-cli compare";
constexpr const char* kCsvHint = "give the compare.csv written by spira-cli compare";

// A figure of compare.json; a strategy that failed has null (or nothing) there.
double figure(const nlohmann::json& j, const char* key, const std::string& what)
{
  return j.contains(key) && !j[key].is_null() ? json_read::number(j, key, what, kJsonHint) : 0.0;
}

// A count in compare.json: a whole number from 0, within what an int holds.
int count(const nlohmann::json& j, const char* key, const std::string& what)
{
  if (!j.contains(key) || j[key].is_null()) return 0;
  const std::int64_t n = json_read::wholeNumber(j, key, what, kJsonHint);
  if (n < 0 || n > std::numeric_limits<int>::max())
    throw InputError(what + ": field '" + key + "' must be a count from 0, found " + std::to_string(n),
                     kJsonHint);
  return static_cast<int>(n);
}

StrategyOutcome& outcomeFor(Comparison& c, const std::string& strategy)
{
  for (StrategyOutcome& s : c.strategies)
    if (s.strategy == strategy) return s;
  StrategyOutcome s;
  s.strategy = strategy;
  s.kind = strategy == "planar_2.5d" ? "planar" : "ctpp";
  s.ran = true;
  c.strategies.push_back(s);
  return c.strategies.back();
}

void readJson(Comparison& c, const fs::path& file)
{
  using namespace json_read;
  const std::string what = file.string();
  const nlohmann::json j = parse(readFile(file), what, kJsonHint);
  if (!j.is_object()) throw InputError(what + ": expected a JSON object, found " + describe(j), kJsonHint);
  c.h = figure(j, "h", what);
  c.hMin = figure(j, "h_min", what);
  c.hMax = figure(j, "h_max", what);
  c.tolerance = figure(j, "height_tolerance_mm", what);
  const auto list = j.find("strategies");
  if (list == j.end() || !list->is_array()) throw InputError(what + " lists no strategies", kJsonHint);
  for (size_t i = 0; i < list->size(); ++i) {
    const nlohmann::json& e = (*list)[i];
    const std::string where = what + " (strategy " + std::to_string(i + 1) + ")";
    if (!e.is_object()) throw InputError(where + ": expected an object, found " + describe(e), kJsonHint);
    StrategyOutcome& s = outcomeFor(c, text(e, "strategy", "?", where, kJsonHint));
    s.kind = text(e, "kind", s.kind, where, kJsonHint);
    s.ran = e.contains("ran") && flag(e, "ran", where, kJsonHint);
    s.feasible = e.contains("feasible") && flag(e, "feasible", where, kJsonHint);
    if (e.contains("failure") && e["failure"].is_string()) s.failure = e["failure"].get<std::string>();
    s.generatrixLengthMin = figure(e, "generatrix_length_min", where);
    s.generatrixLengthMax = figure(e, "generatrix_length_max", where);
    s.depositMin = figure(e, "deposit_min", where);
    s.depositMax = figure(e, "deposit_max", where);
    s.depositMean = figure(e, "deposit_mean", where);
    s.outside = static_cast<size_t>(count(e, "points_outside_window", where));
    s.revolutions = count(e, "revolutions", where);
    s.paths = static_cast<size_t>(count(e, "n_paths", where));
    s.arcStarts = count(e, "n_arc_starts", where);
    s.maxKinkDeg =
        e.contains("max_kink_deg") && !e["max_kink_deg"].is_null() ? figure(e, "max_kink_deg", where) : -1.0;
    s.runtime = figure(e, "runtime_s", where);
  }
}

void readCsv(Comparison& c, const fs::path& file, bool summaries)
{
  std::istringstream in(readFile(file));
  std::string line;
  if (!std::getline(in, line) || line.rfind("strategy,x,y,z,height", 0) != 0)
    throw InputError(file.string() + " does not start with 'strategy,x,y,z,height'", kCsvHint);
  size_t row = 1;
  while (std::getline(in, line)) {
    ++row;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::istringstream fields(line);
    std::string name, cell;
    std::getline(fields, name, ',');
    double v[4];
    for (double& x : v) {
      if (!std::getline(fields, cell, ','))
        throw InputError(file.string() + " line " + std::to_string(row) + " has fewer than 5 fields",
                         kCsvHint);
      std::string problem;
      const std::optional<double> value = parseFiniteNumber(cell, problem);
      if (!value)
        throw InputError(
            file.string() + " line " + std::to_string(row) + ": '" + clippedText(cell) + "' " + problem,
            kCsvHint);
      x = *value;
    }
    StrategyOutcome& s = outcomeFor(c, name);
    s.points.emplace_back(v[0], v[1], v[2]);
    s.heights.push_back(v[3]);
  }
  if (summaries) return;
  // Without compare.json: statistics from the points alone.
  for (StrategyOutcome& s : c.strategies) {
    if (s.heights.empty()) continue;
    const auto [lo, hi] = std::minmax_element(s.heights.begin(), s.heights.end());
    s.depositMin = *lo, s.depositMax = *hi;
    double sum = 0.0;
    for (double h : s.heights) sum += h;
    s.depositMean = sum / static_cast<double>(s.heights.size());
  }
}

}  // namespace

Comparison readComparison(const fs::path& file)
{
  const fs::path dir = fs::is_directory(file) ? file : file.parent_path();
  const fs::path json = fs::is_directory(file) || file.extension() == ".csv" ? dir / "compare.json" : file;
  const fs::path csv = fs::is_directory(file) || file.extension() == ".json" ? dir / "compare.csv" : file;
  const bool hasJson = fs::exists(json), hasCsv = fs::exists(csv);
  if (!hasJson && !hasCsv)
    throw IoError("no compare.json or compare.csv at " + file.string(),
                  "run 'spira-cli compare PART -o DIR' and open DIR/compare.csv");
  Comparison c;
  if (hasJson) readJson(c, json);
  if (hasCsv) readCsv(c, csv, hasJson);
  return c;
}

}  // namespace spira
