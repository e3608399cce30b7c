#include "rapid_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <stdexcept>

namespace spira::test {

namespace {

std::string trim(const std::string& s)
{
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

// Splits on commas outside brackets and quotes.
std::vector<std::string> splitTop(const std::string& s)
{
  std::vector<std::string> out;
  int depth = 0;
  bool quoted = false;
  std::string cur;
  for (char c : s) {
    if (c == '"') quoted = !quoted;
    if (!quoted && c == '[') ++depth;
    if (!quoted && c == ']') --depth;
    if (!quoted && depth == 0 && c == ',') {
      out.push_back(trim(cur));
      cur.clear();
      continue;
    }
    cur += c;
  }
  out.push_back(trim(cur));
  return out;
}

struct Proc {
  std::vector<std::string> statements;
};

}  // namespace

RapidValue parseRapidValue(const std::string& raw)
{
  const std::string text = trim(raw);
  RapidValue v;
  if (!text.empty() && text.front() == '[') {
    if (text.back() != ']') throw std::runtime_error("unbalanced aggregate: " + text);
    v.isList = true;
    const std::string inner = text.substr(1, text.size() - 2);
    if (!trim(inner).empty())
      for (const std::string& item : splitTop(inner)) v.items.push_back(parseRapidValue(item));
    return v;
  }
  if (!text.empty() && text.front() == '"') {
    v.isText = true;
    v.text = text.substr(1, text.size() - 2);
    return v;
  }
  if (text == "TRUE" || text == "FALSE") {
    v.number = text == "TRUE" ? 1.0 : 0.0;
    return v;
  }
  size_t used = 0;
  v.number = std::stod(text, &used);
  if (used != text.size()) throw std::runtime_error("not a number: " + text);
  return v;
}

Transform rapidPose(const RapidValue& target)
{
  const RapidValue& p = target[0];
  const RapidValue& q = target[1];
  double w = q[0].number, x = q[1].number, y = q[2].number, z = q[3].number;
  const double n = std::sqrt(w * w + x * x + y * y + z * z);
  w /= n;
  x /= n;
  y /= n;
  z /= n;
  Mat3 r;
  r << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),   //
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  Transform t = Transform::Identity();
  t.linear() = r;
  t.translation() = Vec3(p[0].number, p[1].number, p[2].number);
  return t;
}

RapidRun runRapid(const std::filesystem::path& dir, const std::string& mainModule)
{
  RapidRun run;
  std::map<std::string, Proc> procs;
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".mod") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& file : files) {
    std::ifstream in(file, std::ios::binary);
    std::string line;
    std::string module, proc;
    size_t number = 0;
    while (std::getline(in, line)) {
      ++number;
      const std::string where = file.filename().string() + ":" + std::to_string(number);
      if (line.empty() || line.back() != '\r') run.problems.push_back(where + ": line does not end in CRLF");
      const std::string s = trim(line);
      if (s.empty() || s[0] == '!') continue;
      if (s.rfind("MODULE ", 0) == 0) {
        module = trim(s.substr(7));
        run.modules.push_back(module);
        if (file.stem().string() != module)
          run.problems.push_back(where + ": module " + module + " in another file");
        continue;
      }
      if (s == "ENDMODULE") {
        module.clear();
        continue;
      }
      if (module.empty()) {
        run.problems.push_back(where + ": text outside a module: " + s);
        continue;
      }
      if (s.rfind("PROC ", 0) == 0) {
        proc = trim(s.substr(5, s.find('(') - 5));
        procs[proc];
        continue;
      }
      if (s == "ENDPROC") {
        proc.clear();
        continue;
      }
      if (s.back() != ';') {
        run.problems.push_back(where + ": statement without ';': " + s);
        continue;
      }
      const std::string stmt = s.substr(0, s.size() - 1);
      if (!proc.empty()) {
        procs[proc].statements.push_back(stmt);
        continue;
      }
      // <storage> <type> <name> := <value>
      std::istringstream words(stmt);
      RapidData d;
      std::string name, assign;
      words >> d.storage >> d.type >> name >> assign;
      if ((d.storage != "PERS" && d.storage != "CONST" && d.storage != "VAR") || assign != ":=") {
        run.problems.push_back(where + ": not a declaration: " + s);
        continue;
      }
      std::string rest;
      std::getline(words, rest);
      try {
        d.value = parseRapidValue(rest);
      } catch (const std::exception& e) {
        run.problems.push_back(where + ": " + e.what());
        continue;
      }
      if (run.data.count(name)) run.problems.push_back(where + ": " + name + " declared twice");
      run.data[name] = d;
    }
    if (!module.empty()) run.problems.push_back(file.filename().string() + ": no ENDMODULE");
  }
  if (std::find(run.modules.begin(), run.modules.end(), mainModule) == run.modules.end())
    run.problems.push_back("no module " + mainModule);

  // Execute main, following calls.
  std::set<std::string> active;
  std::function<void(const std::string&)> exec = [&](const std::string& name) {
    if (!procs.count(name)) {
      run.problems.push_back("call of unknown procedure " + name);
      return;
    }
    if (!active.insert(name).second) {
      run.problems.push_back("recursive call of " + name);
      return;
    }
    for (const std::string& stmt : procs.at(name).statements) {
      const size_t space = stmt.find(' ');
      const std::string head = stmt.substr(0, space);
      if (head == "ConfJ" || head == "ConfL") continue;
      if (space == std::string::npos) {
        exec(head);
        continue;
      }
      RapidMove m;
      m.instruction = head;
      std::string rest = stmt.substr(space + 1);
      if (head == "WaitTime") {
        if (rest.rfind("\\InPos,", 0) == 0) rest = rest.substr(7);
        m.wait = std::stod(rest);
        run.moves.push_back(m);
        continue;
      }
      const size_t wobj = rest.find("\\WObj:=");
      if (wobj != std::string::npos) {
        m.wobj = trim(rest.substr(wobj + 7));
        rest = trim(rest.substr(0, wobj));
      }
      m.args = splitTop(rest);
      m.tool = m.args.back();
      m.args.pop_back();
      const std::set<std::string> known{"MoveJ", "MoveL", "ArcLStart", "ArcL", "ArcLEnd"};
      if (!known.count(head)) run.problems.push_back("unknown instruction " + stmt);
      const size_t expected =
          head == "MoveJ" || head == "MoveL" ? 3 : 5;  // target, speed, [seam, weld,] zone
      if (m.args.size() != expected) run.problems.push_back("wrong argument count: " + stmt);
      run.moves.push_back(m);
    }
    active.erase(name);
  };
  exec("main");
  return run;
}

}  // namespace spira::test
