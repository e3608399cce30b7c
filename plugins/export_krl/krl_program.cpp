#include "krl_program.h"

#include <cmath>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/base/version.h"
#include "spira/export/euler_angles.h"
#include "spira/export/export_params.h"
#include "spira/export/fixed_number.h"
#include "spira/export/program_header.h"
#include "spira/export/program_names.h"
#include "spira/export/program_split.h"

// KRL as written here (KUKA System Software 8.x, KR C4):
// - every program is a .src/.dat pair with the same name; the .dat holds the targets as
//   DECL E6POS XP<i>, where <i> is the plan's point index, the .src the motion;
// - BAS(#INITMOV,0) initialises velocities, accelerations and $APO; $TOOL/$BASE are set
//   directly from TOOL_DATA/BASE_DATA ($NULLFRAME for base 0);
// - the path is LIN ... C_DIS with $APO.CDIS as the approximation distance, exact stops only
//   where the arc is struck and put out and at the end;
// - $VEL.CP (m/s) is assigned only where the commanded speed changes;
// - the arc and the wire feed are switched with path-synchronous TRIGGER WHEN DISTANCE=0/1
//   statements on plain outputs ($OUT, $ANOUT). A trigger is planned with its motion and fires
//   at its point of the path, so no I/O statement stops the advance run between approximated
//   moves (003_abf6ea7743219370.txt §3.5.3: a standalone output statement there would stop the robot at every
//   setpoint and over-deposit);
// - a long path is split into parts <name>_001.. that the main program calls in order; the
//   advance run and approximation continue across the calls, and the arc, switched by triggers
//   in the first and last parts, stays on in between;
// - a plan with several sub-paths has one arc per sub-path; between them the torch retracts,
//   travels and approaches with exact LIN moves and the arc off, and the move from one sub-path's
//   side to the next is a PTP (the arm configuration, S and T, may change there);
// - a dwell (path/dwell.h) puts the arc out, lifts the torch along its axis with an exact LIN,
//   waits there with WAIT SEC (which stops the advance run: nothing is approximated across it)
//   and comes back to strike a new arc, with the weld job set again as at a sub-path's start;
// - with a led wire feed (export_path.h) each setpoint fires its lead time before its point, on
//   the move during which that time falls: DISTANCE=0 with a positive DELAY in the first half of
//   the move, DISTANCE=1 with a negative DELAY in the second half, so the delay never reaches past
//   the move's own start (KSS 8 bounds a negative DELAY by the start of the motion block).
namespace spira {

namespace {

constexpr const char* kEol = "\r\n";
constexpr int kMmDecimals = 3;
constexpr int kDegDecimals = 4;
constexpr int kSpeedDecimals = 5;   // m/s: 0.01 mm/s
constexpr int kAnalogDecimals = 4;  // $ANOUT is -1.0 .. 1.0
constexpr int kWaitDecimals = 3;    // WAIT SEC: ms, the interpolation cycle's order
constexpr size_t kCommentWidth = 100;
constexpr const char* kJobSignal = "SPIRA_JOB";

class KrlWriter {
 public:
  KrlWriter(const ExportPath& path, const KrlSettings& settings, const std::vector<std::string>& header)
      : path_(path), s_(settings), header_(header)
  {
    if (path_.hasLead && s_.process != ProcessCommand::Speed) planLeadTriggers();
  }

  std::vector<OutputFile> run(Progress& progress)
  {
    const size_t n = path_.points.size();
    const size_t positions = n + (path_.hasApproach ? 2 : 0);
    const std::vector<IndexRange> parts =
        positions > s_.maxPoints ? splitEvenly(n - 1, s_.maxPoints) : std::vector<IndexRange>{};
    const ProgramNames names = splitProgramNames(s_.programName, parts.size(), krlNameRules());

    // Written in execution order (main start, parts, main end) so that speed and analog values
    // are only repeated where the running program actually changes them.
    std::vector<OutputFile> files;
    std::string src, dat;
    openProgram(src, dat, names.main);
    for (const auto& line : header_) comment(src, line);
    if (!parts.empty())
      comment(src, "split into " + std::to_string(parts.size()) +
                       " parts called in order; the arc stays on across the calls");
    openBody(src, dat);
    if (parts.empty()) writeMoves(1, n, src, dat, progress);
    for (size_t p = 0; p < parts.size(); ++p) {
      line(src, names.parts[p] + "( )");
      std::string psrc, pdat;
      openProgram(psrc, pdat, names.parts[p]);
      comment(psrc, header_.empty() ? std::string(kApplicationName) : header_.front());
      comment(psrc, "part " + std::to_string(p + 1) + " of " + std::to_string(parts.size()) + " of " +
                        names.main + ", points " + std::to_string(parts[p].begin + 1) + " to " +
                        std::to_string(parts[p].end) + "; called by " + names.main + ", do not run alone");
      declareJobSignal(psrc);
      writeMoves(parts[p].begin + 1, parts[p].end + 1, psrc, pdat, progress);
      line(psrc, "END");
      line(pdat, "ENDDAT");
      files.push_back({names.parts[p] + ".src", std::move(psrc)});
      files.push_back({names.parts[p] + ".dat", std::move(pdat)});
    }
    closeBody(src, dat);
    files.insert(files.begin(),
                 {{names.main + ".src", std::move(src)}, {names.main + ".dat", std::move(dat)}});
    return files;
  }

 private:
  static void line(std::string& out, const std::string& text)
  {
    out += text;
    out += kEol;
  }

  static void comment(std::string& out, const std::string& text)
  {
    for (const auto& l : wrapText(plainText(text), kCommentWidth)) line(out, "; " + l);
  }

  void openProgram(std::string& src, std::string& dat, const std::string& name) const
  {
    for (std::string* out : {&src, &dat}) {
      line(*out, "&ACCESS RVP");
      line(*out, "&REL 1");
      line(*out, std::string("&COMMENT ") + kApplicationName + " WAAM deposition program");
    }
    line(src, "DEF " + name + "( )");
    line(dat, "DEFDAT " + name);
    comment(dat, std::string("targets of ") + name + " written by " + kApplicationName + " " + kVersion);
  }

  // Initialisation, the first (PTP) move and the approach to the first point.
  // The job outputs as one signal, declared in every program that may assign it.
  void declareJobSignal(std::string& src) const
  {
    if (s_.jobOutput > 0)
      line(src, std::string("SIGNAL ") + kJobSignal + " $OUT[" + std::to_string(s_.jobOutput) + "] TO $OUT[" +
                    std::to_string(s_.jobOutput + s_.jobBits - 1) + "]");
  }

  void openBody(std::string& src, std::string& dat)
  {
    declareJobSignal(src);
    line(src, ";FOLD INI");
    line(src, "BAS(#INITMOV,0)");
    line(src, ";ENDFOLD (INI)");
    line(src, "$TOOL=TOOL_DATA[" + std::to_string(s_.tool) + "]");
    line(src,
         s_.base > 0 ? "$BASE=BASE_DATA[" + std::to_string(s_.base) + "]" : std::string("$BASE=$NULLFRAME"));
    line(src, "$ADVANCE=3");
    if (s_.cdis > 0.0) {
      std::string t = "$APO.CDIS=";
      appendFixed(t, s_.cdis, kMmDecimals);
      line(src, t);
    }
    if (s_.jobOutput > 0) line(src, std::string(kJobSignal) + "=" + std::to_string(s_.weldJob));
    line(src, "BAS(#VEL_PTP," + std::to_string(s_.jointSpeed) + ")");
    const ExportPoint& first = path_.points.front();
    warnIfFlagged(src, 0);
    if (path_.hasApproach) {
      declare(dat, "XAPPROACH", path_.approach, first);
      line(src, "PTP XAPPROACH");
      setSpeed(src, s_.approachSpeed);
      line(src, "LIN XP0");
    } else {
      line(src, "PTP XP0");
    }
    if (first.dwell > 0.0) line(src, "WAIT SEC " + waitText(first.dwell));
    declare(dat, "XP0", first.pose, first);
  }

  void closeBody(std::string& src, std::string& dat)
  {
    if (path_.hasApproach) {
      setSpeed(src, s_.approachSpeed);
      line(src, "LIN XRETRACT");
      declare(dat, "XRETRACT", path_.retract, path_.points.back());
    }
    line(src, "END");
    line(dat, "ENDDAT");
  }

  void writeMoves(size_t begin, size_t end, std::string& src, std::string& dat, Progress& progress)
  {
    const size_t n = path_.points.size();
    for (size_t k = begin; k < end; ++k) {
      if ((k & 4095) == 0) {
        progress.checkCancel();
        progress.report(0.5 + 0.4 * static_cast<double>(k) / static_cast<double>(n), "writing KRL");
      }
      const ExportPoint& p = path_.points[k];
      const std::string name = "XP" + std::to_string(k);
      warnIfFlagged(src, k);
      if (p.transfer) comment(src, "travel to sub-path " + std::to_string(p.path) + ", arc off");
      if (p.dwell > 0.0) comment(src, "dwell: torch lifted, arc off, wait " + waitText(p.dwell) + " s");
      if (!p.transfer) setSpeed(src, p.speed);
      if (!leadTriggers_.empty())
        for (const std::string& t : leadTriggers_[k]) line(src, t);
      else if (p.writeWfs && s_.process != ProcessCommand::Speed)
        setWireFeed(src, p.wfs, k);
      if (path_.points[k - 1].strike) {
        if (s_.jobOutput > 0 && s_.endJob > 0 &&
            (path_.points[k - 1].path != path_.points.front().path || dwelled_))
          line(src, std::string("TRIGGER WHEN DISTANCE=0 DELAY=0 DO ") + kJobSignal + "=" +
                        std::to_string(s_.weldJob) + " ; weld job at XP" + std::to_string(k - 1));
        line(src, "TRIGGER WHEN DISTANCE=0 DELAY=0 DO $OUT[" + std::to_string(s_.arcOutput) +
                      "]=TRUE ; arc on at XP" + std::to_string(k - 1));
        dwelled_ = false;
      }
      if (p.stop && s_.jobOutput > 0 && s_.endJob > 0)
        line(src, std::string("TRIGGER WHEN DISTANCE=1 DELAY=0 DO ") + kJobSignal + "=" +
                      std::to_string(s_.endJob) + " ; end job at " + name);
      if (p.stop)
        line(src, "TRIGGER WHEN DISTANCE=1 DELAY=0 DO $OUT[" + std::to_string(s_.arcOutput) +
                      "]=FALSE ; arc off at " + name);
      const bool exact = s_.cdis <= 0.0 || p.strike || p.stop || !p.inArc || k + 1 == n;
      line(src, (p.transfer ? "PTP " : "LIN ") + name + (exact ? "" : " C_DIS"));
      if (p.dwell > 0.0) {
        line(src, "WAIT SEC " + waitText(p.dwell));
        dwelled_ = true;
      }
      declare(dat, name, p.pose, p);
    }
  }

  // The led setpoints as triggers on the moves during which they fire (see the file comment).
  void planLeadTriggers()
  {
    const size_t n = path_.points.size();
    std::vector<double> time(n, 0.0);
    for (size_t k = 1; k < n; ++k) time[k] = time[k - 1] + path_.points[k].moveTime;
    leadTriggers_.resize(n);
    size_t strike = 0;
    std::string last;
    for (size_t k = 0; k < n; ++k) {
      const ExportPoint& p = path_.points[k];
      if (p.strike) strike = k;
      if (!p.writeWfs) continue;
      const std::string value = analogText(p.wfs, k);
      if (value == last) continue;
      last = value;
      const double fire = time[k] - p.wfsLead;
      size_t m = strike + 1;
      while (m < k && time[m] < fire) ++m;
      const double start = time[m - 1], end = time[m];
      std::string t;
      if (fire <= start || fire - start <= 0.5 * (end - start))
        t = "TRIGGER WHEN DISTANCE=0 DELAY=" +
            std::to_string(std::llround(1000.0 * std::max(0.0, fire - start)));
      else
        t = "TRIGGER WHEN DISTANCE=1 DELAY=-" + std::to_string(std::llround(1000.0 * (end - fire)));
      leadTriggers_[m].push_back(t + " DO $ANOUT[" + std::to_string(s_.wfsOutput) + "]=" + value +
                                 " ; WFS of XP" + std::to_string(k));
    }
  }

  static std::string waitText(double seconds)
  {
    std::string text;
    appendFixed(text, seconds, kWaitDecimals);
    return text;
  }

  void warnIfFlagged(std::string& src, size_t k) const
  {
    const std::string& problem = path_.points[k].problem;
    if (!problem.empty()) comment(src, "WARNING (forced export): XP" + std::to_string(k) + " " + problem);
  }

  void setSpeed(std::string& src, double mmPerS)
  {
    std::string text;
    appendFixed(text, mmPerS / 1000.0, kSpeedDecimals);
    if (text == speedText_) return;
    speedText_ = text;
    line(src, "$VEL.CP=" + text);
  }

  std::string analogText(double wfs, size_t k) const
  {
    const double value = wfsAnalogValue(wfs, s_.wfsOffset, s_.wfsGain);
    if (!(value >= -1.0 && value <= 1.0))
      throw InputError("the wire feed of point " + std::to_string(k) + " maps to $ANOUT value " +
                           std::to_string(value) + ", outside KRL's range -1 .. 1",
                       "lower wfs_gain or wfs_offset so offset + gain x WFS stays within -1 .. 1");
    std::string text;
    appendFixed(text, value, kAnalogDecimals);
    return text;
  }

  void setWireFeed(std::string& src, double wfs, size_t k)
  {
    const std::string text = analogText(wfs, k);
    if (text == analogText_) return;
    analogText_ = text;
    line(src, "TRIGGER WHEN DISTANCE=0 DELAY=0 DO $ANOUT[" + std::to_string(s_.wfsOutput) + "]=" + text);
  }

  void declare(std::string& dat, const std::string& name, const Transform& pose, const ExportPoint& p) const
  {
    std::string t = "DECL E6POS " + name + "={X ";
    appendFixed(t, pose.translation().x(), kMmDecimals);
    t += ",Y ";
    appendFixed(t, pose.translation().y(), kMmDecimals);
    t += ",Z ";
    appendFixed(t, pose.translation().z(), kMmDecimals);
    const KukaAbc abc = kukaAbcFromRotation(pose.linear());
    t += ",A ";
    appendFixed(t, radToDeg(abc.a), kDegDecimals);
    t += ",B ";
    appendFixed(t, radToDeg(abc.b), kDegDecimals);
    t += ",C ";
    appendFixed(t, radToDeg(abc.c), kDegDecimals);
    if (path_.hasJoints) t += ",S " + std::to_string(p.kukaStatus) + ",T " + std::to_string(p.kukaTurn);
    if (path_.hasPositioner) {
      t += ",E1 ";
      appendFixed(t, p.externalDeg[0], kDegDecimals);
      t += ",E2 ";
      appendFixed(t, p.externalDeg[1], kDegDecimals);
    }
    t += "}";
    line(dat, t);
  }

  const ExportPath& path_;
  const KrlSettings& s_;
  const std::vector<std::string>& header_;
  std::string speedText_;
  std::string analogText_;
  std::vector<std::vector<std::string>> leadTriggers_;  // by move; empty without a lead
  bool dwelled_ = false;  // a dwell put the arc out (and the end job on) since the last strike
};

}  // namespace

std::vector<OutputFile> writeKrlProgram(const ExportPath& path, const KrlSettings& settings,
                                        const std::vector<std::string>& header, Progress& progress)
{
  return KrlWriter(path, settings, header).run(progress);
}

std::string krlProgramName(const std::string& wanted)
{
  return sanitizeProgramName(wanted, krlNameRules());
}

}  // namespace spira
