#include "tp_reader.h"

#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>

#include "spira/base/units.h"

namespace fs = std::filesystem;

namespace spira::test {

namespace {

std::string trim(const std::string& s)
{
  const size_t b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return {};
  const size_t e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

bool startsWith(const std::string& s, const std::string& prefix)
{
  return s.compare(0, prefix.size(), prefix) == 0;
}

// "KEY = value unit" pieces of a position line, by key. CONFIG is taken out first (it holds commas).
std::map<std::string, double> numbersOf(std::string line, std::string* config)
{
  const size_t c = line.find("CONFIG");
  if (c != std::string::npos && config) {
    const size_t q1 = line.find('\'', c);
    const size_t q2 = line.find('\'', q1 + 1);
    *config = line.substr(q1 + 1, q2 - q1 - 1);
    line.erase(c, q2 + 1 - c);
  }
  std::map<std::string, double> out;
  std::stringstream items(line);
  std::string item;
  while (std::getline(items, item, ',')) {
    const size_t sep = item.find_first_of("=:");
    if (sep == std::string::npos) continue;
    out[trim(item.substr(0, sep))] = std::atof(item.c_str() + sep + 1);
  }
  return out;
}

void readPositions(const std::vector<std::string>& lines, size_t from, TpFile& f)
{
  TpPosition pos;
  int index = -1;
  bool inGp2 = false;
  for (size_t i = from; i < lines.size(); ++i) {
    const std::string line = trim(lines[i]);
    if (line == "/END") return;
    if (startsWith(line, "P[")) {
      index = std::atoi(line.c_str() + 2);
      pos = TpPosition{};
      inGp2 = false;
    } else if (line == "GP1:") {
      inGp2 = false;
    } else if (line == "GP2:") {
      inGp2 = true;
      pos.gp2 = true;
    } else if (line == "};") {
      if (!f.positions.emplace(index, pos).second)
        f.problems.push_back("P[" + std::to_string(index) + "] twice");
    } else {
      std::string config;
      const auto v = numbersOf(line, &config);
      if (!config.empty()) pos.config = config;
      for (const auto& [key, value] : v) {
        if (key == "UF" && !inGp2)
          pos.uf = static_cast<int>(value);
        else if (key == "UT" && !inGp2)
          pos.ut = static_cast<int>(value);
        else if (key == "X")
          pos.xyz.x() = value;
        else if (key == "Y")
          pos.xyz.y() = value;
        else if (key == "Z")
          pos.xyz.z() = value;
        else if (key == "W")
          pos.w = value;
        else if (key == "P")
          pos.p = value;
        else if (key == "R")
          pos.r = value;
        else if (key.size() == 2 && key[0] == 'J') {
          const int k = key[1] - '1';
          if (inGp2 && k >= 0 && k < 2) pos.e[static_cast<size_t>(k)] = value;
          if (!inGp2 && k >= 0 && k < 6) {
            pos.j[static_cast<size_t>(k)] = value;
            pos.joint = true;
          }
        }
      }
    }
  }
  f.problems.push_back("no /END");
}

}  // namespace

TpFile readTpFile(const fs::path& file)
{
  TpFile f;
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  const std::string text = s.str();
  std::vector<std::string> lines;
  size_t start = 0;
  while (start < text.size()) {
    const size_t lf = text.find('\n', start);
    if (lf == std::string::npos) {
      f.problems.push_back("last line has no CRLF");
      lines.push_back(text.substr(start));
      break;
    }
    if (lf == start || text[lf - 1] != '\r') f.problems.push_back("a line ends without CRLF");
    lines.push_back(text.substr(start, lf - start - (lf > start && text[lf - 1] == '\r' ? 1 : 0)));
    start = lf + 1;
  }
  size_t i = 0;
  if (lines.empty() || !startsWith(lines[0], "/PROG  ")) {
    f.problems.push_back("no /PROG line");
    return f;
  }
  f.progName = lines[0].substr(7);
  for (i = 1; i < lines.size() && lines[i] != "/MN"; ++i) {
    const size_t eq = lines[i].find('=');
    if (eq == std::string::npos) continue;
    std::string value = trim(lines[i].substr(eq + 1));
    if (!value.empty() && (value.back() == ';' || value.back() == ',')) value.pop_back();
    f.attributes[trim(lines[i].substr(0, eq))] = value;
  }
  for (++i; i < lines.size() && lines[i] != "/POS"; ++i) {
    const std::string& l = lines[i];
    const size_t colon = l.find(':');
    if (colon == std::string::npos || l.size() < colon + 3 || l.compare(l.size() - 2, 2, " ;") != 0) {
      f.problems.push_back("bad /MN line '" + l + "'");
      continue;
    }
    TpLine tl;
    tl.number = std::atoi(l.substr(0, colon).c_str());
    tl.type = l[colon + 1];
    tl.body = trim(l.substr(colon + 2, l.size() - 2 - (colon + 2)));
    if (tl.type != 'L' && tl.type != 'J') {
      tl.type = ' ';
      if (l.compare(colon + 1, 2, "  ") != 0)
        f.problems.push_back("non-motion line not indented: '" + l + "'");
    }
    f.lines.push_back(tl);
  }
  readPositions(lines, i + 1, f);
  return f;
}

TpRun runTp(const fs::path& dir, const std::string& mainName)
{
  TpRun run;
  std::vector<std::string> comments;
  std::function<void(const std::string&)> program = [&](const std::string& name) {
    run.programs.push_back(name);
    TpFile f = readTpFile(dir / (name + ".ls"));
    for (const auto& p : f.problems) run.problems.push_back(name + ": " + p);
    if (f.progName != name) run.problems.push_back(name + ": /PROG says '" + f.progName + "'");
    if (f.attributes["LINE_COUNT"] != std::to_string(f.lines.size()))
      run.problems.push_back(name + ": LINE_COUNT " + f.attributes["LINE_COUNT"] + " for " +
                             std::to_string(f.lines.size()) + " lines");
    for (size_t i = 0; i < f.lines.size(); ++i)
      if (f.lines[i].number != static_cast<int>(i + 1))
        run.problems.push_back(name + ": line " + std::to_string(i + 1) + " numbered " +
                               std::to_string(f.lines[i].number));
    for (const auto& line : f.lines) {
      if (line.type == ' ') {
        if (startsWith(line.body, "!")) {
          comments.push_back(line.body.substr(1));
          continue;
        }
        run.statements.push_back(line.body);
        if (startsWith(line.body, "CALL ")) program(line.body.substr(5));
        if (startsWith(line.body, "Arc Start[")) run.arcStartAfter.push_back(run.moves.size() - 1);
        if (startsWith(line.body, "Arc End[")) run.arcEndAfter.push_back(run.moves.size() - 1);
        if (startsWith(line.body, "WAIT ")) {
          const size_t close = line.body.find("(sec)");
          if (close == std::string::npos || close + 5 != line.body.size())
            run.problems.push_back(name + ": bad WAIT '" + line.body + "'");
          run.waitAfter.push_back(run.moves.size() - 1);
          run.waitSeconds.push_back(std::atof(line.body.c_str() + 5));
        }
        continue;
      }
      TpMove m;
      m.program = name;
      m.type = line.type;
      std::istringstream s(line.body);
      std::string p;
      s >> p >> m.speed >> m.termination;
      std::getline(s, m.options);
      m.options = trim(m.options);
      m.index = std::atoi(p.c_str() + 2);
      const auto it = f.positions.find(m.index);
      if (it == f.positions.end())
        run.problems.push_back(name + ": " + p + " has no position");
      else
        m.pos = it->second;
      m.comments = std::move(comments);
      comments.clear();
      run.moves.push_back(std::move(m));
    }
  };
  program(mainName);
  return run;
}

Transform tpPose(const TpPosition& p)
{
  Transform pose = Transform::Identity();
  // FANUC: W, P, R about the fixed X, Y, Z axes, applied in that order.
  pose.linear() =
      (Eigen::AngleAxisd(degToRad(p.r), Vec3::UnitZ()) * Eigen::AngleAxisd(degToRad(p.p), Vec3::UnitY()) *
       Eigen::AngleAxisd(degToRad(p.w), Vec3::UnitX()))
          .toRotationMatrix();
  pose.translation() = p.xyz;
  return pose;
}

}  // namespace spira::test
