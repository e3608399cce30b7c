#include "spira/kinematics/fanuc_config.h"

#include <cctype>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/kinematics/angle_wrap.h"

namespace spira {

std::string FanucConfig::format() const
{
  std::ostringstream s;
  s << (flip ? 'F' : 'N') << ' ' << (up ? 'U' : 'D') << ' ' << (front ? 'T' : 'B') << ", " << turns[0] << ", "
    << turns[1] << ", " << turns[2];
  return s.str();
}

FanucConfig FanucConfig::parse(const std::string& text)
{
  const auto bad = [&text]() {
    return InputError("'" + text + "' is not a FANUC CONFIG",
                      "write it as in a TP position, e.g. 'N U T, 0, 0, 0'");
  };
  std::string letters;
  std::array<int, 3> turns{};
  size_t turnCount = 0;
  std::istringstream in(text);
  std::string token;
  while (std::getline(in, token, ',')) {
    std::string t;
    for (char c : token)
      if (!std::isspace(static_cast<unsigned char>(c))) t += c;
    if (letters.empty()) {
      letters = t;
      continue;
    }
    if (turnCount == 3) throw bad();
    try {
      size_t used = 0;
      turns[turnCount++] = std::stoi(t, &used);
      if (used != t.size()) throw bad();
    } catch (const std::logic_error&) {
      throw bad();
    }
  }
  if (letters.size() != 3 || turnCount != 3) throw bad();
  FanucConfig c;
  const auto pick = [&](char v, char yes, char no) {
    const char u = static_cast<char>(std::toupper(static_cast<unsigned char>(v)));
    if (u != yes && u != no) throw bad();
    return u == yes;
  };
  c.flip = pick(letters[0], 'F', 'N');
  c.up = pick(letters[1], 'U', 'D');
  c.front = pick(letters[2], 'T', 'B');
  c.turns = turns;
  return c;
}

int fanucTurnNumber(double deg)
{
  return deg >= 0.0 ? static_cast<int>(std::floor((deg + 180.0) / 360.0))
                    : -static_cast<int>(std::floor((-deg + 180.0) / 360.0));
}

FanucConfig fanucConfig(const OpwModel& model, const JointVector& q)
{
  const JointVector theta = model.toOpw(q);
  FanucConfig c;
  c.flip = q[4] >= 0.0;
  c.up = model.elbowAngle(theta) >= 0.0;
  c.front = model.wristReach(theta) >= 0.0;
  c.turns = {fanucTurnNumber(radToDeg(q[0])), fanucTurnNumber(radToDeg(q[3])),
             fanucTurnNumber(radToDeg(q[5]))};
  return c;
}

std::optional<JointVector> fanucJointsFrom(const ArmIk& ik, const Transform& baseTip,
                                           const FanucConfig& config)
{
  for (const IkSolution& s : ik.solveAll(baseTip)) {
    if (fanucConfig(ik.model(), s.q) != config) continue;
    // The CONFIG has no J3 turn number, yet the J3 range is wider than a turn: take J3 in (-180, 180].
    JointVector q = s.q;
    q[2] = q[1] + wrapToPi(q[2] - q[1]);
    if (ik.limitMargin(q) >= 0.0) return q;
    if (s.withinLimits) return s.q;
  }
  return std::nullopt;
}

}  // namespace spira
