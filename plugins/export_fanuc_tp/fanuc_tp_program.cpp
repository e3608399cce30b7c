#include "fanuc_tp_program.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "fanuc_tp_positions.h"
#include "spira/base/version.h"
#include "spira/export/export_params.h"
#include "spira/export/program_header.h"
#include "spira/export/program_names.h"
#include "spira/export/program_split.h"

// FANUC TP as written here (R-30iB, ArcTool), in the ASCII .ls form the controller and its
// offline tools (MakeTP/ROBOGUIDE) read:
// - /PROG, /ATTR (LINE_COUNT = the number of /MN lines, DEFAULT_GROUP 1,*,*,*,* or 1,1,*,*,*
//   with a positioner as motion group 2), /APPL (ARC Welding Equipment 1), /MN, /POS, /END;
//   CRLF line endings, /MN lines numbered 1..LINE_COUNT without gaps;
// - the path is "L P[i] <speed> CNT<n>", FINE where the arc is struck and put out and at the
//   end; speeds per move from the TS channel (whole mm/sec or cm/min, or the planned move time
//   in msec); positions XYZWPR with the CONFIG string (or J1..J6), GP2 J1/J2 for the positioner;
// - "Arc Start[n]" after the move to the first deposition point and "Arc End[n]" after the last
//   one, once each;
// - the wire feed on AO[n] rides on the motion line before the move it belongs to as the point
//   logic "TA 0.00sec,AO[n]=v", so it switches at the path point instead of stopping the look-ahead;
// - a plan with several sub-paths has one Arc Start / Arc End per sub-path; between them the
//   torch retracts, travels and approaches with FINE L moves and the arc off, and the move from
//   one sub-path's side to the next is a J move (the CONFIG may change there);
// - a dwell (path/dwell.h) ends the arc with Arc End, lifts the torch along its axis with a FINE
//   L move, waits there with "WAIT t(sec)" and comes back with a FINE L move to strike again with
//   Arc Start;
// - with a led wire feed (export_path.h) each setpoint rides on the move during which it is due as
//   "TB t sec,AO[n]=v" (t before that move's end point, never more than the move lasts); a
//   motion line takes one such option, so of two setpoints due in one move the later is written;
// - a long path is split into parts <NAME>_001.. that the main program CALLs in order; ArcTool
//   keeps the weld on across the calls until Arc End (seed 004 ran its points from two
//   alternating sub-programs this way on an R-30iB Plus).
namespace spira {

namespace {

constexpr const char* kEol = "\r\n";
constexpr size_t kCommentWidth = 32;  // the pendant shows and keeps 32 characters of a comment

// One TP program being written: /MN lines are numbered as they come, /POS entries likewise.
class TpProgram {
 public:
  void statement(const std::string& text)
  {
    number();
    mn_ += "  ";
    mn_ += text;
    mn_ += " ;";
    mn_ += kEol;
  }

  void motion(char type, const std::string& text)
  {
    number();
    mn_ += type;
    mn_ += text;
    mn_ += " ;";
    mn_ += kEol;
  }

  void comment(const std::string& text)
  {
    for (const auto& l : wrapText(plainText(text, ";"), kCommentWidth)) statement("!" + l);
  }

  size_t addPosition() { return ++positions_; }
  std::string& positions() { return pos_; }

  std::string finish(const std::string& name, const TpSettings& s, bool positioner) const
  {
    std::string out;
    auto line = [&out](const std::string& text) {
      out += text;
      out += kEol;
    };
    line("/PROG  " + name);
    line("/ATTR");
    line("OWNER\t\t= MNEDITOR;");
    line(std::string("COMMENT\t\t= \"") + kApplicationName + " WAAM\";");
    line("PROG_SIZE\t= 0;");
    const std::string stamp = dateStamp(s.date);
    if (!stamp.empty()) {
      line("CREATE\t\t= " + stamp + ";");
      line("MODIFIED\t= " + stamp + ";");
    }
    line("FILE_NAME\t= ;");
    line("VERSION\t\t= 0;");
    line("LINE_COUNT\t= " + std::to_string(lines_) + ";");
    line("MEMORY_SIZE\t= 0;");
    line("PROTECT\t\t= READ_WRITE;");
    line("TCD:  STACK_SIZE\t= 0,");
    line("      TASK_PRIORITY\t= 50,");
    line("      TIME_SLICE\t= 0,");
    line("      BUSY_LAMP_OFF\t= 0,");
    line("      ABORT_REQUEST\t= 0,");
    line("      PAUSE_REQUEST\t= 0;");
    line(std::string("DEFAULT_GROUP\t= ") + (positioner ? "1,1,*,*,*;" : "1,*,*,*,*;"));
    line("CONTROL_CODE\t= 00000000 00000000;");
    line("/APPL");
    line("  ARC : TRUE ;");
    line("  ARC Welding Equipment : 1,*,*,*,*;");
    line("/MN");
    out += mn_;
    line("/POS");
    out += pos_;
    line("/END");
    return out;
  }

 private:
  void number()
  {
    char buf[24];
    std::snprintf(buf, sizeof buf, "%4zu:", ++lines_);
    mn_ += buf;
  }

  // "DATE 24-05-01  TIME 12:30:00" from "2024-05-01[ 12:30[:00]]"; empty when `date` is not one.
  static std::string dateStamp(const std::string& date)
  {
    int y = 0, mo = 0, d = 0, h = 0, mi = 0, sec = 0;
    const int read = std::sscanf(date.c_str(), "%4d-%2d-%2d%*[ T]%2d:%2d:%2d", &y, &mo, &d, &h, &mi, &sec);
    if (read < 3 || mo < 1 || mo > 12 || d < 1 || d > 31 || h > 23 || mi > 59 || sec > 59) return {};
    char buf[96];
    std::snprintf(buf, sizeof buf, "DATE %02d-%02d-%02d  TIME %02d:%02d:%02d", y % 100, mo, d, h, mi, sec);
    return buf;
  }

  std::string mn_;
  std::string pos_;
  size_t lines_ = 0;
  size_t positions_ = 0;
};

class TpWriter {
 public:
  TpWriter(const ExportPath& path, const TpSettings& settings, const std::vector<std::string>& header)
      : path_(path), s_(settings), header_(header)
  {
    frames_.uframe = s_.uframe;
    frames_.utool = s_.utool;
    frames_.positioner = path_.hasPositioner;
    if (path_.hasLead && s_.process != ProcessCommand::Speed) planLeadOptions();
  }

  TpOutput run(Progress& progress)
  {
    const size_t n = path_.points.size();
    const size_t positions = n + (path_.hasApproach ? 2 : 0);
    const std::vector<IndexRange> parts =
        positions > s_.maxPoints ? splitEvenly(n - 1, s_.maxPoints) : std::vector<IndexRange>{};
    const ProgramNames names = splitProgramNames(s_.programName, parts.size(), fanucNameRules());

    TpOutput out;
    TpProgram main;
    for (const auto& l : header_) main.comment(l);
    if (!parts.empty())
      main.comment("split into " + std::to_string(parts.size()) + " parts, arc on across the calls");
    main.statement("UTOOL_NUM=" + std::to_string(s_.utool));
    main.statement("UFRAME_NUM=" + std::to_string(s_.uframe));
    writeStart(main);
    if (parts.empty()) writeMoves(1, n, main, progress);
    for (size_t p = 0; p < parts.size(); ++p) {
      main.statement("CALL " + names.parts[p]);
      TpProgram part;
      part.comment(header_.empty() ? std::string(kApplicationName) : header_.front());
      part.comment("part " + std::to_string(p + 1) + " of " + std::to_string(parts.size()) + " of " +
                   names.main + ", points " + std::to_string(parts[p].begin + 1) + " to " +
                   std::to_string(parts[p].end) + "; called by " + names.main + ", do not run alone");
      writeMoves(parts[p].begin + 1, parts[p].end + 1, part, progress);
      out.files.push_back({names.parts[p] + ".ls", part.finish(names.parts[p], s_, path_.hasPositioner)});
    }
    if (path_.hasApproach) {
      const Transform& last = path_.points.back().pose;
      const size_t index = main.addPosition();
      main.motion('L', " P[" + std::to_string(index) + "] " +
                           approachSpeedText((path_.retract.translation() - last.translation()).norm()) +
                           " FINE");
      appendCartesianPosition(main.positions(), index, path_.retract, config(n - 1),
                              path_.points.back().externalDeg, frames_);
    }
    out.files.insert(out.files.begin(),
                     OutputFile{names.main + ".ls", main.finish(names.main, s_, path_.hasPositioner)});
    out.worstSpeedError = worstSpeedError_;
    out.worstSpeedWanted = worstSpeedWanted_;
    out.worstSpeedMove = worstSpeedMove_;
    return out;
  }

 private:
  // The joint move to the approach point (or to the first point) and the linear approach.
  void writeStart(TpProgram& main)
  {
    const ExportPoint& first = path_.points.front();
    warnIfFlagged(main, 0);
    const std::string joint = std::to_string(s_.jointSpeed) + "%";
    if (path_.hasApproach) {
      const size_t index = main.addPosition();
      main.motion('J', " P[" + std::to_string(index) + "] " + joint + " FINE");
      appendCartesianPosition(main.positions(), index, path_.approach, config(0), first.externalDeg, frames_);
      const double d = (first.pose.translation() - path_.approach.translation()).norm();
      writeMove(main, 0, approachSpeedText(d));
    } else {
      writeMove(main, 0, joint);
    }
  }

  // The led setpoints as point logic on the moves during which they are due.
  void planLeadOptions()
  {
    const size_t n = path_.points.size();
    std::vector<double> time(n, 0.0);
    for (size_t k = 1; k < n; ++k) time[k] = time[k - 1] + path_.points[k].moveTime;
    leadOptions_.assign(n, std::string());
    size_t strike = 0;
    std::string last;
    for (size_t k = 0; k < n; ++k) {
      const ExportPoint& p = path_.points[k];
      if (p.strike) strike = k;
      if (!p.writeWfs) continue;
      const std::string value = analogValueText(p.wfs);
      if (value == last) continue;
      last = value;
      const double fire = time[k] - p.wfsLead;
      const std::string ao = ",AO[" + std::to_string(s_.wfsOutput) + "]=" + value;
      if (fire <= time[strike] + 0.005) {
        leadOptions_[strike] = " TA 0.00sec" + ao;  // in force as the arc is struck
        continue;
      }
      size_t m = strike + 1;
      while (m < k && time[m] < fire) ++m;
      char buf[32];
      std::snprintf(buf, sizeof buf, " TB %.2fsec", std::max(0.0, time[m] - fire));
      leadOptions_[m] = buf + ao;
    }
  }

  std::string analogValueText(double wfs) const
  {
    return std::to_string(
        static_cast<long long>(std::llround(wfsAnalogValue(wfs, s_.wfsOffset, s_.wfsGain))));
  }

  void writeMoves(size_t begin, size_t end, TpProgram& program, Progress& progress)
  {
    const size_t n = path_.points.size();
    for (size_t k = begin; k < end; ++k) {
      if ((k & 4095) == 0) {
        progress.checkCancel();
        progress.report(0.5 + 0.4 * static_cast<double>(k) / static_cast<double>(n), "writing TP");
      }
      warnIfFlagged(program, k);
      if (path_.points[k].transfer)
        program.comment("travel to sub-path " + std::to_string(path_.points[k].path) + ", arc off");
      if (path_.points[k].dwell > 0.0) program.comment("dwell: torch lifted, arc off");
      writeMove(program, k,
                path_.points[k].transfer ? std::to_string(s_.jointSpeed) + "%" : pathSpeedText(k));
    }
  }

  // Move k with its position, the wire-feed point logic for move k + 1, and the arc switching.
  void writeMove(TpProgram& program, size_t k, const std::string& speed)
  {
    const size_t n = path_.points.size();
    const ExportPoint& p = path_.points[k];
    const bool fine = k == 0 || p.strike || p.stop || !p.inArc || k + 1 == n;
    const size_t index = program.addPosition();
    std::string text = " P[" + std::to_string(index) + "] " + speed + " " +
                       (fine ? std::string("FINE") : "CNT" + std::to_string(s_.cnt));
    if (!leadOptions_.empty()) {
      text += leadOptions_[k];
    } else if (k + 1 < n && path_.points[k + 1].writeWfs && s_.process != ProcessCommand::Speed) {
      const std::string valueText = analogValueText(path_.points[k + 1].wfs);
      if (valueText != analogText_) {
        analogText_ = valueText;
        text += " TA 0.00sec,AO[" + std::to_string(s_.wfsOutput) + "]=" + valueText;
      }
    }
    const char type = (k == 0 && !path_.hasApproach) || p.transfer ? 'J' : 'L';
    program.motion(type, text);
    if (s_.jointPositions)
      appendJointPosition(program.positions(), index, p.robotDeg, p.externalDeg, frames_);
    else
      appendCartesianPosition(program.positions(), index, p.pose, config(k), p.externalDeg, frames_);
    if (p.dwell > 0.0) {
      char buf[40];
      std::snprintf(buf, sizeof buf, "WAIT %.2f(sec)", p.dwell);
      program.statement(buf);
    }
    if (p.strike) program.statement("Arc Start[" + std::to_string(s_.weldSchedule) + "]");
    if (p.stop) program.statement("Arc End[" + std::to_string(s_.endSchedule) + "]");
  }

  void warnIfFlagged(TpProgram& program, size_t k) const
  {
    const std::string& problem = path_.points[k].problem;
    if (!problem.empty()) program.comment("FORCED: point " + std::to_string(k) + " " + problem);
  }

  const std::string& config(size_t k) const
  {
    const std::string& c = path_.points[k].fanucConfig;
    return path_.hasJoints && !c.empty() ? c : s_.defaultConfig;
  }

  std::string approachSpeedText(double distance) const
  {
    switch (s_.speedUnit) {
      case TpSpeedUnit::MmPerSec:
        return std::to_string(std::max(1LL, std::llround(s_.approachSpeed))) + "mm/sec";
      case TpSpeedUnit::CmPerMin:
        return std::to_string(std::max(1LL, std::llround(s_.approachSpeed * 6.0))) + "cm/min";
      case TpSpeedUnit::Msec:
        return std::to_string(std::max(1LL, std::llround(1000.0 * distance / s_.approachSpeed))) + "msec";
    }
    return {};
  }

  std::string pathSpeedText(size_t k)
  {
    const ExportPoint& p = path_.points[k];
    double written = 0.0, wanted = 0.0;
    std::string text;
    switch (s_.speedUnit) {
      case TpSpeedUnit::MmPerSec: {
        const long long v = std::max(1LL, std::llround(p.speed));
        text = std::to_string(v) + "mm/sec";
        written = static_cast<double>(v);
        wanted = p.speed;
        break;
      }
      case TpSpeedUnit::CmPerMin: {
        const long long v = std::max(1LL, std::llround(p.speed * 6.0));
        text = std::to_string(v) + "cm/min";
        written = static_cast<double>(v) / 6.0;
        wanted = p.speed;
        break;
      }
      case TpSpeedUnit::Msec: {
        const double step = (p.pose.translation() - path_.points[k - 1].pose.translation()).norm();
        wanted = step > 1e-9 ? step / p.speed : p.moveTime;
        const long long ms = std::max(1LL, std::llround(1000.0 * wanted));
        text = std::to_string(ms) + "msec";
        written = static_cast<double>(ms) / 1000.0;
        break;
      }
    }
    if (wanted > 0.0 && std::abs(written - wanted) / wanted > worstSpeedError_) {
      worstSpeedError_ = std::abs(written - wanted) / wanted;
      worstSpeedWanted_ = p.speed;
      worstSpeedMove_ = k;
    }
    return text;
  }

  const ExportPath& path_;
  const TpSettings& s_;
  const std::vector<std::string>& header_;
  TpPositionFrames frames_;
  std::string analogText_;
  std::vector<std::string> leadOptions_;  // by move; empty without a lead
  double worstSpeedError_ = 0.0;
  double worstSpeedWanted_ = 0.0;
  size_t worstSpeedMove_ = 0;
};

}  // namespace

TpOutput writeTpProgram(const ExportPath& path, const TpSettings& settings,
                        const std::vector<std::string>& header, Progress& progress)
{
  return TpWriter(path, settings, header).run(progress);
}

std::string tpProgramName(const std::string& wanted)
{
  return sanitizeProgramName(wanted, fanucNameRules());
}

}  // namespace spira
