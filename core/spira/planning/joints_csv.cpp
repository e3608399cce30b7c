#include "spira/planning/joints_csv.h"

#include "spira/base/number_text.h"

namespace spira {

std::string jointsCsv(const JointTrajectory& joints)
{
  std::string out = "index,q1,q2,q3,q4,q5,q6,e1,e2,config,reachable,dexterity,collision\n";
  out.reserve(out.size() + joints.size() * 160);
  const bool fanuc = joints.controller == "fanuc_r30ib";
  const bool abb = joints.controller == "abb_irc5";
  for (size_t i = 0; i < joints.size(); ++i) {
    const JointPoint& p = joints.points[i];
    appendNumber(out, static_cast<long long>(i));
    for (double q : p.robotDeg) {
      out += ',';
      appendNumber(out, q);
    }
    for (double e : p.externalDeg) {
      out += ',';
      if (joints.hasPositioner) appendNumber(out, e);
    }
    if (fanuc) {
      out += ",\"" + p.fanucConfig + "\"";
    } else if (abb) {
      out += ",\"[" + std::to_string(p.abbConf[0]) + "," + std::to_string(p.abbConf[1]) + "," +
             std::to_string(p.abbConf[2]) + "," + std::to_string(p.abbConf[3]) + "]\"";
    } else {
      out += ",S" + std::to_string(p.kukaStatus) + " T" + std::to_string(p.kukaTurn);
    }
    out += p.reachable ? ",1," : ",0,";
    appendNumber(out, p.dexterity);
    out += p.collision ? ",1\n" : ",0\n";
  }
  return out;
}

}  // namespace spira
