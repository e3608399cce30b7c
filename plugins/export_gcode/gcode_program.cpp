#include "gcode_program.h"

#include <algorithm>
#include <map>

#include "spira/export/fixed_number.h"
#include "spira/export/program_header.h"

namespace spira {

namespace {

constexpr size_t kCommentWidth = 72;
constexpr int kFeedDecimals = 1;
// A move planned shorter than this (a repeated point) is given this duration: F stays finite.
constexpr double kShortestMoveS = 1e-3;
// Inverse-time feeds are small numbers (a 3 s move is F20): three places keep them within 0.01 %.
constexpr int kInverseTimeDecimals = 3;

std::string filled(const std::string& templ, const std::string& field, const std::string& value)
{
  std::string out = templ;
  for (size_t at = out.find(field); at != std::string::npos; at = out.find(field, at + value.size()))
    out.replace(at, field.size(), value);
  return out;
}

class ProgramText {
 public:
  ProgramText(const GcodeSettings& s) : s_(s) {}

  void raw(const std::string& line) { text_ += line + "\n"; }

  void comment(const std::string& line)
  {
    for (const std::string& part : wrapText(plainText(line, "()"), kCommentWidth)) raw("(" + part + ")");
  }

  void block(const std::string& line)
  {
    if (s_.lineNumbers) text_ += "N" + std::to_string(++number_) + " ";
    raw(line);
  }

  std::string& text() { return text_; }

 private:
  const GcodeSettings& s_;
  std::string text_;
  long long number_ = 0;
};

class Writer {
 public:
  Writer(const GcodeMachine& m, const GcodeSettings& s) : m_(m), s_(s), out_(s) {}

  ProgramText& out() { return out_; }

  void move(const char* code, const HeadAxes& a, double feed)
  {
    std::string line = code;
    for (size_t k = 0; k < 3; ++k) word(line, m_.linear[k].letter, a.linear[static_cast<Eigen::Index>(k)]);
    for (size_t k = 0; k < 2; ++k) word(line, m_.rotary[k].letter, a.rotaryDeg[k]);
    if (feed > 0.0) {
      std::string f;
      appendFixed(f, feed, s_.inverseTime ? kInverseTimeDecimals : kFeedDecimals);
      // In G93 every G1 must carry its F.
      if (f != feed_ || s_.inverseTime) {
        line += " F" + f;
        feed_ = f;
      }
    }
    out_.block(line);
  }

  void wireFeed(double wfsMmPerS)
  {
    std::string v;
    appendFixed(v, wireFeedInUnit(wfsMmPerS, m_.wireFeedUnit), s_.decimals);
    if (v == wfs_) return;
    out_.block(filled(m_.wireFeed, "{wfs}", v));
    wfs_ = v;
  }

  void dwell(double seconds)
  {
    std::string v;
    appendFixed(v, seconds, 3);
    out_.block(filled(m_.dwell, "{s}", v));
  }

 private:
  void word(std::string& line, const std::string& letter, double value) const
  {
    line += " " + letter;
    appendFixed(line, value, s_.decimals);
  }

  const GcodeMachine& m_;
  const GcodeSettings& s_;
  ProgramText out_;
  std::string feed_;  // F is modal: written when it changes
  std::string wfs_;   // the last wire-feed value written
};

// The wire-feed setpoint written after reaching each point (before the move out of it). Without a
// lead the setpoint of point k starts move k, so it is written after point k-1; with a lead it is
// written after the last point reached before its due time, never before its arc's strike.
std::map<size_t, double> wireFeedSlots(const ExportPath& path)
{
  std::map<size_t, double> slots;
  const auto& pts = path.points;
  std::vector<double> t(pts.size(), 0.0);
  for (size_t i = 1; i < pts.size(); ++i) t[i] = t[i - 1] + pts[i].moveTime;
  size_t strike = 0;
  for (size_t k = 0; k < pts.size(); ++k) {
    if (pts[k].strike) strike = k;
    if (!pts[k].writeWfs) continue;
    size_t slot = k > strike ? k - 1 : strike;
    if (path.hasLead) {
      const double due = t[k] - pts[k].wfsLead;
      slot = k;
      while (slot > strike && t[slot] > due) --slot;
    }
    slots[slot] = pts[k].wfs;
  }
  return slots;
}

// The F of a path move: its planned speed, or in inverse time its planned duration.
double feedOf(const GcodeSettings& s, const ExportPoint& p)
{
  if (!s.inverseTime) return p.speed * 60.0;
  return 60.0 / std::max(p.moveTime, kShortestMoveS);
}

// The F of an approach or retract move from `a` to `b` at the approach speed.
double approachFeedOf(const GcodeSettings& s, const Vec3& a, const Vec3& b)
{
  if (!s.inverseTime) return s.approachFeed;
  return s.approachFeed / std::max((b - a).norm(), s.approachFeed * kShortestMoveS / 60.0);
}

}  // namespace

double wireFeedInUnit(double wfsMmPerS, const std::string& unit)
{
  if (unit == "m/min") return wfsMmPerS * 0.06;
  if (unit == "mm/s") return wfsMmPerS;
  return wfsMmPerS * 60.0;
}

std::string writeGcodeProgram(const ExportPath& path, const GcodeTargets& targets, const GcodeMachine& m,
                              const GcodeSettings& s, const std::vector<std::string>& header,
                              Progress& progress)
{
  Writer w(m, s);
  ProgramText& out = w.out();
  out.raw("%");
  if (s.programNumber > 0) out.raw("O" + std::to_string(s.programNumber));
  for (const std::string& line : header) out.comment(line);
  out.block(s.inverseTime ? "G21 G90 G93" : "G21 G90 G94");
  const size_t n = path.points.size();
  w.move("G0", path.hasApproach ? targets.approach : targets.points.front(), 0.0);
  const std::map<size_t, double> slots = wireFeedSlots(path);
  for (size_t i = 0; i < n; ++i) {
    if ((i & 4095) == 0) {
      progress.checkCancel();
      progress.report(0.5 + 0.4 * static_cast<double>(i) / static_cast<double>(n), "writing the program");
    }
    const ExportPoint& p = path.points[i];
    if (i > 0 || path.hasApproach) {
      const Vec3 from = i > 0 ? path.points[i - 1].pose.translation() : path.approach.translation();
      w.move("G1", targets.points[i], i == 0 ? approachFeedOf(s, from, p.pose.translation()) : feedOf(s, p));
    }
    if (p.stop) out.block(m.arcOff);
    if (p.dwell > 0.0) w.dwell(p.dwell);
    if (p.strike) {
      w.wireFeed(p.wfs);
      out.block(m.arcOn);
    }
    const auto slot = slots.find(i);
    if (slot != slots.end()) w.wireFeed(slot->second);
  }
  if (path.hasApproach)
    w.move("G1", targets.retract,
           approachFeedOf(s, path.points.back().pose.translation(), path.retract.translation()));
  out.block(m.programEnd);
  out.raw("%");
  return std::move(out.text());
}

}  // namespace spira
