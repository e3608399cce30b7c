#include "real/plan_files_reader.h"

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace spira::test::real {

std::vector<PathPoint> readTrajectoryCsv(const std::filesystem::path& file)
{
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot open " + file.string());
  std::string line;
  std::getline(in, line);
  std::map<std::string, size_t> column;
  {
    std::stringstream s(line);
    std::string name;
    for (size_t k = 0; std::getline(s, name, ','); ++k) column[name] = k;
  }
  const char* needed[] = {"x", "y", "z", "bx", "by", "bz", "arc", "path"};
  for (const char* c : needed)
    if (!column.count(c)) throw std::runtime_error(file.string() + ": no column '" + c + "' in the header");
  std::vector<PathPoint> pts;
  std::vector<double> v;
  for (size_t lineNo = 2; std::getline(in, line); ++lineNo) {
    if (line.empty()) continue;
    v.clear();
    std::stringstream s(line);
    std::string cell;
    while (std::getline(s, cell, ',')) v.push_back(std::stod(cell));
    if (v.size() < column.size())
      throw std::runtime_error(file.string() + " line " + std::to_string(lineNo) + ": too few columns");
    PathPoint p;
    p.p = V3(v[column["x"]], v[column["y"]], v[column["z"]]);
    p.b = V3(v[column["bx"]], v[column["by"]], v[column["bz"]]);
    p.arc = v[column["arc"]] != 0.0;
    p.path = static_cast<int>(v[column["path"]]);
    pts.push_back(p);
  }
  return pts;
}

namespace {

void take(const nlohmann::json& j, CheckSettings& s)
{
  if (!j.is_object()) return;
  auto num = [&](const char* key, double& target) {
    if (j.contains(key) && j[key].is_number()) target = j[key].get<double>();
  };
  num("h_min", s.hMin);
  num("h_max", s.hMax);
  num("tol", s.tol);
  num("bead_width", s.beadWidth);
  num("substrate_z", s.substrateZ);
}

}  // namespace

CheckSettings settingsFromReport(const std::filesystem::path& reportJson, CheckSettings given)
{
  std::ifstream in(reportJson);
  if (!in) throw std::runtime_error("cannot open " + reportJson.string());
  const nlohmann::json j = nlohmann::json::parse(in);
  take(j, given);
  if (j.contains("window")) take(j["window"], given);
  if (j.contains("deposit_check")) take(j["deposit_check"], given);
  return given;
}

}  // namespace spira::test::real
