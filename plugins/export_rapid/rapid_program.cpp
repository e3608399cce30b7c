#include "rapid_program.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <Eigen/Geometry>

#include "rapid_names.h"
#include "spira/base/error.h"
#include "spira/base/version.h"
#include "spira/export/fixed_number.h"
#include "spira/export/program_header.h"
#include "spira/export/program_names.h"
#include "spira/export/program_split.h"

// RAPID as written here (IRC5, RobotWare 6 with RobotWare Arc; references: "Technical reference
// manual - RAPID Instructions, Functions and Data types" 3HAC050917-001 for robtarget, confdata,
// tooldata, wobjdata, speeddata, zonedata, MoveJ/MoveL, ConfL, WaitTime; "Application manual - Arc
// and Arc Sensor" 3HAC050988-001 for ArcLStart/ArcL/ArcLEnd, seamdata and welddata):
// - one module <name>.mod (MODULE ... ENDMODULE) with the data and PROC main(); past max_points
//   the robtargets and moves go to part modules <name>_001.. whose procedures main() calls in order,
//   and <name>.pgf lists the modules for loading as one program. ArcL's motion and the arc carry on
//   across the calls (a procedure call is not a stop point for the look-ahead);
// - PERS tooldata (the cell's torch as tframe, a load estimate), PERS wobjdata (the identity: the
//   targets are in the robot base frame of the solved cell, i.e. the world frame of a one-robot
//   cell), PERS seamdata and one PERS welddata per distinct weld speed and wire feed;
// - CONST robtarget p<i> per plan point: [[x,y,z],[q1,q2,q3,q4],[cf1,cf4,cf6,cfx],[eax_a..eax_f]]
//   with the quaternion's scalar first, normalised and with q1 >= 0, the confdata of the solved
//   joints, and the positioner's E1/E2 in eax_a/eax_b (degrees), 9E9 for the unused axes;
// - the weld speed: RobotWare Arc runs ArcL at the welddata's weld_speed while the arc burns; the
//   speeddata argument applies only when welding is blocked (test runs) and on the way to the
//   start. So each distinct move speed (three significant digits) gets a welddata with that weld_speed, and
//   a speeddata of the same v_tcp for the dry run. The wire feed (arcdata wirefeed, m/min) follows
//   the WFS channel in the analog process modes; in "speed" mode it is 0 and the schedule sets it;
// - ArcLStart moves to the point where the arc is struck, ArcL through the arc, ArcLEnd to the point
//   where it is put out: exactly one of each per arc (one per sub-path, one more per dwell);
//   fine at the arc's ends, zN in between; travel moves with the arc off are MoveL fine, and the
//   move from one sub-path's side to the next a MoveJ (the configuration may change there);
// - ConfJ\On and ConfL\Off: the joint moves reach the written configuration; the linear moves follow
//   the path with the closest one, as the solver kept one cfx along each sub-path and cf1/cf4/cf6
//   may step where an axis crosses a quadrant;
// - a dwell (path/dwell.h) ends the arc with ArcLEnd, lifts the torch with MoveL fine, waits with
//   WaitTime\InPos and comes back with ArcLStart.
namespace spira {

namespace {

constexpr const char* kEol = "\r\n";
constexpr int kMmDecimals = 3;
constexpr int kQuatDecimals = 8;
constexpr int kDegDecimals = 4;
constexpr int kSpeedDecimals = 1;  // v_tcp of the approach and travel moves, mm/s
constexpr int kWireDecimals = 2;   // wirefeed, m/min
constexpr size_t kCommentWidth = 100;
constexpr double kMmPerSPerMPerMin = 1000.0 / 60.0;

void line(std::string& out, const std::string& text, int indent = 1)
{
  out.append(static_cast<size_t>(2 * indent), ' ');
  out += text;
  out += kEol;
}

void comment(std::string& out, const std::string& text, int indent = 1)
{
  for (const auto& l : wrapText(plainText(text), kCommentWidth)) line(out, "! " + l, indent);
}

std::string fixed(double x, int decimals)
{
  std::string s;
  appendFixed(s, x, decimals);
  return s;
}

// [x,y,z],[q1,q2,q3,q4]: a pose with ABB's quaternion (scalar first, q1 >= 0), the first two
// components of a pose or robtarget.
void appendPose(std::string& t, const Transform& pose)
{
  Eigen::Quaterniond q(pose.linear());
  q.normalize();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  t += "[";
  appendFixed(t, pose.translation().x(), kMmDecimals);
  t += ',';
  appendFixed(t, pose.translation().y(), kMmDecimals);
  t += ',';
  appendFixed(t, pose.translation().z(), kMmDecimals);
  t += "],[";
  appendFixed(t, q.w(), kQuatDecimals);
  t += ',';
  appendFixed(t, q.x(), kQuatDecimals);
  t += ',';
  appendFixed(t, q.y(), kQuatDecimals);
  t += ',';
  appendFixed(t, q.z(), kQuatDecimals);
  t += "]";
}

// A weld speed to three significant digits (at least 0.00001 mm/s): with a positioner turning the
// part under the torch the TCP moves slowly in the base frame (tenths of mm/s), where fixed
// decimals would distort the planned move times.
std::string speedValueText(double mmPerS)
{
  const auto decimalsOf = [](double v) {
    return std::clamp(2 - static_cast<int>(std::floor(std::log10(v))), 0, 5);
  };
  const double v = std::max(mmPerS, 1e-5);
  // Rounded first, so that 9.9999 and 10.0001 both give "10.0" (one welddata, not two).
  const double scale = std::pow(10.0, decimalsOf(v));
  const double rounded = std::round(v * scale) / scale;
  return fixed(rounded, decimalsOf(rounded));
}

class RapidWriter {
 public:
  RapidWriter(const ExportPath& path, const RapidSettings& settings, const std::vector<std::string>& header)
      : path_(path), s_(settings), header_(header)
  {
  }

  RapidOutput run(Progress& progress)
  {
    const size_t n = path_.points.size();
    const size_t positions = n + (path_.hasApproach ? 2 : 0);
    const std::vector<IndexRange> parts =
        positions > s_.maxPoints ? splitEvenly(n - 1, s_.maxPoints) : std::vector<IndexRange>{};
    // Part modules hold a procedure named like the module plus "_run": leave room for it.
    ProgramNameRules partRules = rapidNameRules();
    partRules.maxLength -= 4;
    const std::vector<std::string> partNames =
        splitProgramNames(s_.moduleName, parts.size(), partRules).parts;

    // The process data first: every move's welddata and speeddata are known before any module is
    // written, so the main module can declare them all.
    assignProcessData();

    std::string targets, body;
    if (path_.hasApproach) declareTarget(targets, "pApproach", path_.approach, path_.points.front());
    declareTarget(targets, "p0", path_.points.front().pose, path_.points.front());
    writeStart(body);
    if (parts.empty()) writeMoves(1, n, targets, body, progress);
    RapidOutput out;
    for (size_t p = 0; p < parts.size(); ++p) {
      line(body, partNames[p] + "_run;", 2);
      std::string partTargets, partBody;
      writeMoves(parts[p].begin + 1, parts[p].end + 1, partTargets, partBody, progress);
      std::string mod = "MODULE " + partNames[p] + kEol;
      comment(mod, header_.empty() ? std::string(kApplicationName) : header_.front());
      comment(mod, "part " + std::to_string(p + 1) + " of " + std::to_string(parts.size()) + " of " +
                       s_.moduleName + ", points " + std::to_string(parts[p].begin + 1) + " to " +
                       std::to_string(parts[p].end) + "; called by " + s_.moduleName + ", do not run alone");
      mod += partTargets;
      line(mod, "PROC " + partNames[p] + "_run()");
      mod += partBody;
      line(mod, "ENDPROC");
      mod += std::string("ENDMODULE") + kEol;
      out.files.push_back({partNames[p] + ".mod", std::move(mod)});
    }
    writeEnd(targets, body);

    std::string mod = "MODULE " + s_.moduleName + kEol;
    for (const auto& l : header_) comment(mod, l);
    if (!parts.empty())
      comment(mod, "split into " + std::to_string(parts.size()) + " part modules called in order (" +
                       s_.moduleName + ".pgf loads them all); the arc stays on across the calls");
    declareData(mod);
    mod += targets;
    line(mod, "PROC main()");
    mod += body;
    line(mod, "ENDPROC");
    mod += std::string("ENDMODULE") + kEol;
    out.files.insert(out.files.begin(), OutputFile{s_.moduleName + ".mod", std::move(mod)});
    if (!parts.empty()) {
      std::string pgf =
          std::string("<?xml version=\"1.0\" encoding=\"ISO-8859-1\" ?>") + kEol + "<Program>" + kEol;
      pgf += "\t<Module>" + s_.moduleName + ".mod</Module>" + kEol;
      for (const std::string& name : partNames) pgf += "\t<Module>" + name + ".mod</Module>" + kEol;
      pgf += std::string("</Program>") + kEol;
      out.files.push_back({s_.moduleName + ".pgf", std::move(pgf)});
    }
    out.weldDataCount = weldNames_.size();
    out.worstSpeedError = worstSpeedError_;
    return out;
  }

 private:
  // One speeddata per distinct move speed and one welddata per distinct (speed, wire feed), named
  // in order of first use.
  void assignProcessData()
  {
    const size_t n = path_.points.size();
    moveSpeed_.assign(n, std::string());
    moveWeld_.assign(n, std::string());
    double wfs = path_.points.front().wfs;
    for (size_t k = 0; k < n; ++k) {
      const ExportPoint& p = path_.points[k];
      if (p.writeWfs || p.strike) wfs = p.wfs;
      if (k == 0 || p.transfer) continue;
      const std::string speedText = speedValueText(p.speed);
      const double written = std::stod(speedText);
      if (p.speed > 0.0) worstSpeedError_ = std::max(worstSpeedError_, std::abs(written - p.speed) / p.speed);
      auto sp = speedNames_.find(speedText);
      if (sp == speedNames_.end()) {
        sp = speedNames_.emplace(speedText, s_.speedPrefix + std::to_string(speedNames_.size() + 1)).first;
        speedOrder_.push_back(speedText);
      }
      moveSpeed_[k] = sp->second;
      if (!p.inArc || p.strike) continue;  // the move to a strike point runs before the arc
      const std::string wireText = s_.wireFeed ? fixed(wfs / kMmPerSPerMPerMin, kWireDecimals) : "0";
      const std::string key = speedText + "," + wireText;
      auto wd = weldNames_.find(key);
      if (wd == weldNames_.end()) {
        wd = weldNames_.emplace(key, s_.weldPrefix + std::to_string(weldNames_.size() + 1)).first;
        weldOrder_.push_back(key);
      }
      moveWeld_[k] = wd->second;
    }
  }

  void declareData(std::string& mod) const
  {
    std::string t = "PERS tooldata " + s_.toolName + " := [TRUE,[";
    appendPose(t, s_.flangeTcp);
    t += ']';
    const Vec3 cog = 0.5 * s_.flangeTcp.translation();
    t += ",[" + fixed(s_.toolMass, 3) + ",[" + fixed(cog.x(), 1) + "," + fixed(cog.y(), 1) + "," +
         fixed(cog.z(), 1) + "],[1,0,0,0],0,0,0]];";
    line(mod, t);
    line(mod,
         "PERS wobjdata " + s_.wobjName + " := [FALSE,TRUE,\"\",[[0,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];");
    // purge, preflow, ign_arc, ign_move_delay, scrape_start, heat_speed/time/distance, heat_arc,
    // cool_time, fill_time, fill_arc, bback_time, rback_time, bback_arc, postflow_time.
    const std::string arc0 =
        "[" + std::to_string(s_.schedule) + ",0," + fixed(s_.voltage, 1) + ",0,0,0,0,0,0]";
    line(mod, "PERS seamdata " + s_.seamName + " := [0.5,0.5," + arc0 + ",0,0,0,0,0," + arc0 + ",0,0," +
                  arc0 + ",0,0," + arc0 + ",0.5];");
    // weld_speed, org_weld_speed, main_arc [sched, mode, voltage, wirefeed, control, current, ...],
    // org_arc.
    for (const std::string& key : weldOrder_) {
      const size_t comma = key.find(',');
      line(mod, "PERS welddata " + weldNames_.at(key) + " := [" + key.substr(0, comma) + ",0,[" +
                    std::to_string(s_.schedule) + ",0," + fixed(s_.voltage, 1) + "," + key.substr(comma + 1) +
                    ",0,0,0,0,0],[0,0,0,0,0,0,0,0,0]];");
    }
    for (const std::string& speed : speedOrder_)
      line(mod, "CONST speeddata " + speedNames_.at(speed) + " := [" + speed + ",500,5000,1000];");
    line(mod, "CONST speeddata " + s_.speedPrefix + "Approach := [" +
                  fixed(s_.approachSpeed, kSpeedDecimals) + ",500,5000,1000];");
    line(mod, "CONST speeddata " + s_.speedPrefix + "Travel := [" + fixed(s_.travelSpeed, kSpeedDecimals) +
                  ",500,5000,1000];");
  }

  std::string toolArgs() const { return ", " + s_.toolName + " \\WObj:=" + s_.wobjName + ";"; }

  void writeStart(std::string& body)
  {
    const ExportPoint& first = path_.points.front();
    line(body, "ConfJ \\On;", 2);
    line(body, "ConfL \\Off;", 2);
    warnIfFlagged(body, 0);
    if (path_.hasApproach) {
      line(body, "MoveJ pApproach, " + s_.speedPrefix + "Travel, fine" + toolArgs(), 2);
      if (first.strike)
        line(body,
             "ArcLStart p0, " + s_.speedPrefix + "Approach, " + s_.seamName + ", " + firstWeld() + ", fine" +
                 toolArgs(),
             2);
      else
        line(body, "MoveL p0, " + s_.speedPrefix + "Approach, fine" + toolArgs(), 2);
    } else {
      line(body, "MoveJ p0, " + s_.speedPrefix + "Travel, fine" + toolArgs(), 2);
      if (first.strike)
        line(body,
             "ArcLStart p0, " + s_.speedPrefix + "Approach, " + s_.seamName + ", " + firstWeld() + ", fine" +
                 toolArgs(),
             2);
    }
    if (first.dwell > 0.0) line(body, "WaitTime \\InPos, " + fixed(first.dwell, 3) + ";", 2);
  }

  void writeEnd(std::string& targets, std::string& body) const
  {
    if (!path_.hasApproach) return;
    line(body, "MoveL pRetract, " + s_.speedPrefix + "Approach, fine" + toolArgs(), 2);
    declareTarget(targets, "pRetract", path_.retract, path_.points.back());
  }

  // The welddata the arc struck at point 0 starts with: that of the first move inside it.
  std::string firstWeld() const
  {
    for (size_t k = 1; k < moveWeld_.size(); ++k)
      if (!moveWeld_[k].empty()) return moveWeld_[k];
    return s_.weldPrefix + "1";
  }

  void writeMoves(size_t begin, size_t end, std::string& targets, std::string& body, Progress& progress)
  {
    const size_t n = path_.points.size();
    for (size_t k = begin; k < end; ++k) {
      if ((k & 4095) == 0) {
        progress.checkCancel();
        progress.report(0.5 + 0.4 * static_cast<double>(k) / static_cast<double>(n), "writing RAPID");
      }
      const ExportPoint& p = path_.points[k];
      const std::string name = "p" + std::to_string(k);
      declareTarget(targets, name, p.pose, p);
      warnIfFlagged(body, k);
      if (p.transfer) comment(body, "travel to sub-path " + std::to_string(p.path) + ", arc off", 2);
      if (p.dwell > 0.0) comment(body, "dwell: torch lifted, arc off", 2);
      if (p.strike && p.stop)
        throw InputError("point " + std::to_string(k) + " both strikes and puts out an arc",
                         "an arc needs at least two points; plan again");
      if (p.transfer) {
        line(body, "MoveJ " + name + ", " + s_.speedPrefix + "Travel, fine" + toolArgs(), 2);
        // A sub-path that deposits from its first point: the arc is struck where the travel ends.
        if (p.strike)
          line(body,
               "ArcLStart " + name + ", " + s_.speedPrefix + "Approach, " + s_.seamName + ", " + nextWeld(k) +
                   ", fine" + toolArgs(),
               2);
      } else if (p.strike) {
        // The move to the strike point runs with the arc off; the arc ignites on arrival.
        line(body,
             "ArcLStart " + name + ", " + moveSpeed_[k] + ", " + s_.seamName + ", " + nextWeld(k) + ", fine" +
                 toolArgs(),
             2);
      } else if (p.stop) {
        line(body,
             "ArcLEnd " + name + ", " + moveSpeed_[k] + ", " + s_.seamName + ", " + moveWeld_[k] + ", fine" +
                 toolArgs(),
             2);
      } else if (p.inArc) {
        const bool exact = s_.zone <= 0 || k + 1 == n;
        line(body,
             "ArcL " + name + ", " + moveSpeed_[k] + ", " + s_.seamName + ", " + moveWeld_[k] + ", " +
                 (exact ? std::string("fine") : "z" + std::to_string(s_.zone)) + toolArgs(),
             2);
      } else {
        line(body, "MoveL " + name + ", " + moveSpeed_[k] + ", fine" + toolArgs(), 2);
      }
      if (p.dwell > 0.0) line(body, "WaitTime \\InPos, " + fixed(p.dwell, 3) + ";", 2);
    }
  }

  // The welddata of the arc struck at k: that of the move after it.
  std::string nextWeld(size_t k) const
  {
    for (size_t m = k + 1; m < moveWeld_.size(); ++m)
      if (!moveWeld_[m].empty()) return moveWeld_[m];
    return s_.weldPrefix + "1";
  }

  void warnIfFlagged(std::string& body, size_t k) const
  {
    const std::string& problem = path_.points[k].problem;
    if (!problem.empty()) comment(body, "WARNING (forced export): p" + std::to_string(k) + " " + problem, 2);
  }

  void declareTarget(std::string& targets, const std::string& name, const Transform& pose,
                     const ExportPoint& p) const
  {
    std::string t = "CONST robtarget " + name + " := [";
    appendPose(t, pose);
    const std::array<int, 4>& c = p.abbConf;
    t += ",[" + std::to_string(c[0]) + "," + std::to_string(c[1]) + "," + std::to_string(c[2]) + "," +
         std::to_string(c[3]) + "],[";
    if (path_.hasPositioner) {
      appendFixed(t, p.externalDeg[0], kDegDecimals);
      t += ',';
      appendFixed(t, p.externalDeg[1], kDegDecimals);
      t += ",9E9,9E9,9E9,9E9]];";
    } else {
      t += "9E9,9E9,9E9,9E9,9E9,9E9]];";
    }
    line(targets, t);
  }

  const ExportPath& path_;
  const RapidSettings& s_;
  const std::vector<std::string>& header_;
  std::vector<std::string> moveSpeed_, moveWeld_;  // by move; empty where not used
  std::map<std::string, std::string> speedNames_, weldNames_;
  std::vector<std::string> speedOrder_, weldOrder_;
  double worstSpeedError_ = 0.0;
};

}  // namespace

RapidOutput writeRapidProgram(const ExportPath& path, const RapidSettings& settings,
                              const std::vector<std::string>& header, Progress& progress)
{
  return RapidWriter(path, settings, header).run(progress);
}

}  // namespace spira
