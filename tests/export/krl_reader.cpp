#include "krl_reader.h"

#include <cstdlib>
#include <sstream>

#include "spira/base/units.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {

namespace {

// Lines split at CRLF; a bare LF or CR is reported as a problem.
std::vector<std::string> crlfLines(const std::string& text, const std::string& what,
                                   std::vector<std::string>& problems)
{
  std::vector<std::string> lines;
  size_t start = 0;
  while (start < text.size()) {
    const size_t lf = text.find('\n', start);
    if (lf == std::string::npos) {
      problems.push_back(what + ": last line has no line ending");
      lines.push_back(text.substr(start));
      break;
    }
    if (lf == start || text[lf - 1] != '\r') problems.push_back(what + ": line without CRLF");
    const size_t end = lf > start && text[lf - 1] == '\r' ? lf - 1 : lf;
    const std::string line = text.substr(start, end - start);
    if (line.find('\r') != std::string::npos) problems.push_back(what + ": stray CR");
    lines.push_back(line);
    start = lf + 1;
  }
  return lines;
}

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

KrlTarget parseAggregate(const std::string& body, std::vector<std::string>& problems)
{
  KrlTarget t;
  std::stringstream items(body);
  std::string item;
  while (std::getline(items, item, ',')) {
    std::istringstream kv(item);
    std::string key;
    double value = 0.0;
    if (!(kv >> key >> value)) {
      problems.push_back("bad E6POS component '" + item + "'");
      continue;
    }
    if (key == "X")
      t.xyz.x() = value;
    else if (key == "Y")
      t.xyz.y() = value;
    else if (key == "Z")
      t.xyz.z() = value;
    else if (key == "A")
      t.a = value;
    else if (key == "B")
      t.b = value;
    else if (key == "C")
      t.c = value;
    else if (key == "S")
      t.s = static_cast<int>(value);
    else if (key == "T")
      t.t = static_cast<int>(value);
    else if (key == "E1")
      t.e1 = value;
    else if (key == "E2")
      t.e2 = value;
    else
      problems.push_back("unknown E6POS component " + key);
  }
  return t;
}

void checkPreamble(const std::vector<std::string>& lines, const std::string& what,
                   std::vector<std::string>& problems)
{
  if (lines.size() < 4 || lines[0] != "&ACCESS RVP" || lines[1] != "&REL 1" ||
      !startsWith(lines[2], "&COMMENT "))
    problems.push_back(what + ": missing &ACCESS/&REL/&COMMENT preamble");
}

struct Runner {
  fs::path dir;
  KrlRun run;
  double vel = 0.0;
  std::vector<std::string> triggers, comments;

  void program(const std::string& name, bool isMain)
  {
    run.programs.push_back(name);
    if (name.size() > 24) run.problems.push_back(name + ": name longer than 24 characters");
    const auto targets = readKrlDat(dir / (name + ".dat"), run.problems);
    const auto lines = crlfLines(readBytes(dir / (name + ".src")), name + ".src", run.problems);
    checkPreamble(lines, name + ".src", run.problems);
    bool inDef = false, ended = false;
    for (const auto& raw : lines) {
      const std::string line = trim(raw);
      if (line.empty() || line[0] == '&') continue;
      if (line[0] == ';') {
        if (!startsWith(line, ";FOLD") && !startsWith(line, ";ENDFOLD"))
          comments.push_back(trim(line.substr(1)));
        continue;
      }
      if (ended) run.problems.push_back(name + ": statement after END");
      if (!inDef) {
        if (line != "DEF " + name + "( )")
          run.problems.push_back(name + ": first statement is '" + line + "'");
        inDef = true;
        continue;
      }
      if (isMain) run.statements.push_back(line);
      if (line == "END") {
        ended = true;
      } else if (startsWith(line, "$VEL.CP=")) {
        vel = std::atof(line.c_str() + 8);
      } else if (startsWith(line, "TRIGGER ")) {
        triggers.push_back(line);
      } else if (startsWith(line, "WAIT SEC ")) {
        if (run.moves.empty()) run.problems.push_back(name + ": WAIT SEC before the first move");
        run.waitAfter.push_back(run.moves.size() - 1);
        run.waitSeconds.push_back(std::atof(line.c_str() + 9));
      } else if (startsWith(line, "LIN ") || startsWith(line, "PTP ")) {
        std::istringstream s(line);
        KrlMove m;
        m.program = name;
        std::string extra;
        s >> m.motion >> m.target >> extra;
        m.approximated = extra == "C_DIS";
        const auto it = targets.find(m.target);
        if (it == targets.end())
          run.problems.push_back(name + ": target " + m.target + " not declared");
        else
          m.pose = it->second;
        m.velCp = vel;
        m.triggers = std::move(triggers);
        m.comments = std::move(comments);
        triggers.clear();
        comments.clear();
        run.moves.push_back(std::move(m));
      } else if (line.size() > 4 && line.compare(line.size() - 3, 3, "( )") == 0) {
        program(line.substr(0, line.size() - 3), false);
      }
    }
    if (!ended) run.problems.push_back(name + ": no END");
  }
};

}  // namespace

std::map<std::string, KrlTarget> readKrlDat(const fs::path& file, std::vector<std::string>& problems)
{
  std::map<std::string, KrlTarget> targets;
  const std::string name = file.stem().string();
  const auto lines = crlfLines(readBytes(file), file.filename().string(), problems);
  checkPreamble(lines, file.filename().string(), problems);
  bool open = false, closed = false;
  for (const auto& raw : lines) {
    const std::string line = trim(raw);
    if (line.empty() || line[0] == '&' || line[0] == ';') continue;
    if (line == "DEFDAT " + name) {
      open = true;
    } else if (line == "ENDDAT") {
      closed = true;
    } else if (startsWith(line, "DECL E6POS ")) {
      const size_t eq = line.find("={");
      const size_t close = line.rfind('}');
      if (eq == std::string::npos || close == std::string::npos || !open || closed) {
        problems.push_back(name + ".dat: bad declaration '" + line + "'");
        continue;
      }
      const std::string target = line.substr(11, eq - 11);
      if (!targets.emplace(target, parseAggregate(line.substr(eq + 2, close - eq - 2), problems)).second)
        problems.push_back(name + ".dat: " + target + " declared twice");
    } else {
      problems.push_back(name + ".dat: unexpected line '" + line + "'");
    }
  }
  if (!open || !closed) problems.push_back(name + ".dat: no DEFDAT/ENDDAT pair");
  return targets;
}

KrlRun runKrl(const fs::path& dir, const std::string& mainName)
{
  Runner r;
  r.dir = dir;
  r.program(mainName, true);
  return r.run;
}

Transform krlPose(const KrlTarget& t)
{
  Transform pose = Transform::Identity();
  pose.linear() =
      (Eigen::AngleAxisd(degToRad(t.a), Vec3::UnitZ()) * Eigen::AngleAxisd(degToRad(t.b), Vec3::UnitY()) *
       Eigen::AngleAxisd(degToRad(t.c), Vec3::UnitX()))
          .toRotationMatrix();
  pose.translation() = t.xyz;
  return pose;
}

}  // namespace spira::test
