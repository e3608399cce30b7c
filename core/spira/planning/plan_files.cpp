#include "spira/planning/plan_files.h"

#include <nlohmann/json.hpp>

#include "spira/base/number_text.h"
#include "spira/path/dwell.h"
#include "spira/path/tool_tilt.h"

namespace spira {
namespace {

void putVec(std::string& out, const Vec3& v)
{
  for (int k = 0; k < 3; ++k) {
    appendNumber(out, v[k]);
    out += ',';
  }
}

constexpr double kMmPerSecondToMetresPerMinute = 60.0 / 1000.0;

}  // namespace

std::string trajectoryCsv(const Trajectory& trajectory)
{
  // The dwell column only when a dwell is planned: plans without one keep the file they always had.
  const bool dwell = hasDwell(trajectory);
  std::string out = "index,x,y,z,nx,ny,nz,tx,ty,tz,bx,by,bz,rev,gen,height,ts,wfs,arc,path";
  // The up direction only for a tilted torch, whose b is not the direction a positioner keeps vertical.
  const bool up = trajectory.extra.count(kUpChannels[0]) != 0;
  out += dwell ? ",dwell_s" : "";
  out += up ? ",ux,uy,uz\n" : "\n";
  out.reserve(out.size() + trajectory.size() * 224);
  for (size_t i = 0; i < trajectory.size(); ++i) {
    const TrajectoryPoint& p = trajectory.points[i];
    appendNumber(out, static_cast<long long>(i));
    out += ',';
    putVec(out, p.position);
    putVec(out, p.normal);
    putVec(out, p.tangent);
    putVec(out, p.build);
    appendNumber(out, static_cast<long long>(p.revolution));
    out += ',';
    appendNumber(out, static_cast<long long>(p.generatrix));
    out += ',';
    appendNumber(out, p.height);
    out += ',';
    appendNumber(out, p.travelSpeed);
    out += ',';
    appendNumber(out, p.wireFeed * kMmPerSecondToMetresPerMinute);
    out += p.arcOn ? ",1," : ",0,";
    appendNumber(out, static_cast<long long>(p.path));
    if (dwell) {
      out += ',';
      appendNumber(out, dwellAt(trajectory, i));
    }
    if (up) {
      out += ',';
      putVec(out, upDirection(trajectory, i));
      out.pop_back();  // putVec's trailing comma
    }
    out += '\n';
  }
  return out;
}

nlohmann::json adviceJson(const PlanAdvice& advice)
{
  return {{"found", advice.found},
          {"change", advice.change},
          {"flags", advice.flags},
          {"tried", advice.tried},
          {"cause", advice.cause}};
}

}  // namespace spira
