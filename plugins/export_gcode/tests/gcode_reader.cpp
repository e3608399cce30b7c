#include "gcode_reader.h"

#include <cctype>
#include <sstream>

namespace spira::test {

namespace {

bool number(const std::string& s, double& out)
{
  if (s.empty()) return false;
  size_t used = 0;
  try {
    out = std::stod(s, &used);
  } catch (...) {
    return false;
  }
  return used == s.size();
}

}  // namespace

GcodeRun readGcode(const std::string& text, const std::string& arcOn, const std::string& arcOff,
                   const std::string& wireFeedPrefix, const std::string& dwellPrefix)
{
  GcodeRun run;
  std::istringstream in(text);
  std::string line;
  std::map<char, double> axes;
  double feed = 0.0, wfs = -1.0;
  bool arc = false;
  size_t lineNo = 0;
  long long lastN = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::string where = "line " + std::to_string(lineNo) + " '" + line + "': ";
    if (line == "%" || line.empty()) continue;
    if (line.front() == '(') {
      if (line.back() != ')' || line.find('(', 1) != std::string::npos || line.find(')') + 1 != line.size())
        run.problems.push_back(where + "a comment must be one ( ) pair");
      continue;
    }
    if (line.front() == 'O') continue;
    if (line.front() == 'N') {
      const size_t sp = line.find(' ');
      const long long n = std::stoll(line.substr(1, sp - 1));
      if (n != lastN + 1) run.problems.push_back(where + "block number out of sequence");
      lastN = n;
      line = line.substr(sp + 1);
    }
    if (line == arcOn) {
      if (arc) run.problems.push_back(where + "arc on while burning");
      arc = true;
      run.events.push_back("arc on");
      continue;
    }
    if (line == arcOff) {
      if (!arc) run.problems.push_back(where + "arc off while off");
      arc = false;
      run.events.push_back("arc off");
      continue;
    }
    double v = 0.0;
    if (line.rfind(wireFeedPrefix, 0) == 0 && number(line.substr(wireFeedPrefix.size()), v)) {
      wfs = v;
      run.wireFeeds.push_back(v);
      run.events.push_back("wire feed");
      continue;
    }
    if (line.rfind(dwellPrefix, 0) == 0 && number(line.substr(dwellPrefix.size()), v)) {
      if (arc) run.problems.push_back(where + "dwell with the arc on");
      run.dwells.push_back(v);
      run.events.push_back("dwell");
      continue;
    }
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "G21" || word == "M30") continue;
    if (word != "G0" && word != "G1") {
      run.problems.push_back(where + "unknown block");
      continue;
    }
    GcodeMove m;
    m.rapid = word == "G0";
    while (words >> word) {
      if (word.size() < 2 || !std::isupper(static_cast<unsigned char>(word[0])) ||
          !number(word.substr(1), v)) {
        run.problems.push_back(where + "bad word " + word);
        continue;
      }
      if (word[0] == 'F')
        feed = v;
      else
        axes[word[0]] = v;
    }
    if (!m.rapid && !(feed > 0.0)) run.problems.push_back(where + "G1 without a feed");
    m.axes = axes;
    m.feed = m.rapid ? 0.0 : feed;
    m.arcOn = arc;
    m.wireFeed = wfs;
    run.moves.push_back(m);
    run.events.push_back("move");
  }
  if (arc) run.problems.push_back("the program ends with the arc on");
  return run;
}

}  // namespace spira::test
