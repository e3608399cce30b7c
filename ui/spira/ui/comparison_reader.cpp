#include "spira/ui/comparison_reader.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "spira/base/error.h"

namespace spira::ui {

namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& file)
{
  std::ifstream in(file, std::ios::binary);
  if (!in) throw IoError("cannot read " + file.string(), "check that the file exists and is readable");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

double num(const nlohmann::json& j, const char* key)
{
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : 0.0;
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
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(slurp(file));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string() + " is not valid JSON: " + e.what(), "run spira-cli compare again");
  }
  c.h = num(j, "h");
  c.hMin = num(j, "h_min");
  c.hMax = num(j, "h_max");
  c.tolerance = num(j, "height_tolerance_mm");
  const auto list = j.find("strategies");
  if (list == j.end() || !list->is_array())
    throw InputError(file.string() + " lists no strategies",
                     "give the compare.json written by spira-cli compare");
  for (const nlohmann::json& e : *list) {
    StrategyOutcome& s = outcomeFor(c, e.value("strategy", std::string("?")));
    s.kind = e.value("kind", s.kind);
    s.ran = e.value("ran", false);
    s.feasible = e.value("feasible", false);
    if (e.contains("failure") && e["failure"].is_string()) s.failure = e["failure"].get<std::string>();
    s.generatrixLengthMin = num(e, "generatrix_length_min");
    s.generatrixLengthMax = num(e, "generatrix_length_max");
    s.depositMin = num(e, "deposit_min");
    s.depositMax = num(e, "deposit_max");
    s.depositMean = num(e, "deposit_mean");
    s.outside = static_cast<size_t>(num(e, "points_outside_window"));
    s.revolutions = static_cast<int>(num(e, "revolutions"));
    s.paths = static_cast<size_t>(num(e, "n_paths"));
    s.runtime = num(e, "runtime_s");
  }
}

void readCsv(Comparison& c, const fs::path& file, bool summaries)
{
  std::istringstream in(slurp(file));
  std::string line;
  if (!std::getline(in, line) || line.rfind("strategy,x,y,z,height", 0) != 0)
    throw InputError(file.string() + " does not start with 'strategy,x,y,z,height'",
                     "give the compare.csv written by spira-cli compare");
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
                         "give the compare.csv written by spira-cli compare");
      try {
        x = std::stod(cell);
      } catch (const std::exception&) {
        throw InputError(file.string() + " line " + std::to_string(row) + ": '" + cell + "' is not a number",
                         "give the compare.csv written by spira-cli compare");
      }
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

}  // namespace spira::ui
