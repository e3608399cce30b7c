#include "fanuc_tp_positions.h"

#include <cctype>

#include "spira/base/units.h"
#include "spira/export/euler_angles.h"
#include "spira/export/fixed_number.h"

namespace spira {

namespace {

constexpr const char* kEol = "\r\n";
constexpr int kMmDecimals = 3;
constexpr int kDegDecimals = 4;

void appendFrames(std::string& out, const TpPositionFrames& frames)
{
  out += "\tUF : " + std::to_string(frames.uframe) + ", UT : " + std::to_string(frames.utool) + ",";
}

void appendPositioner(std::string& out, const std::array<double, 2>& externalDeg,
                      const TpPositionFrames& frames)
{
  if (!frames.positioner) return;
  out += kEol;
  out += "   GP2:";
  out += kEol;
  appendFrames(out, frames);
  out += kEol;
  out += "\tJ1=";
  appendFixed(out, externalDeg[0], kDegDecimals, 11);
  out += " deg,\tJ2=";
  appendFixed(out, externalDeg[1], kDegDecimals, 11);
  out += " deg";
}

void openPosition(std::string& out, size_t index)
{
  out += "P[" + std::to_string(index) + "]{";
  out += kEol;
  out += "   GP1:";
  out += kEol;
}

void closePosition(std::string& out)
{
  out += kEol;
  out += "};";
  out += kEol;
}

}  // namespace

void appendCartesianPosition(std::string& out, size_t index, const Transform& pose, const std::string& config,
                             const std::array<double, 2>& externalDeg, const TpPositionFrames& frames)
{
  openPosition(out, index);
  appendFrames(out, frames);
  out += "\t\tCONFIG : '" + config + "',";
  out += kEol;
  const Vec3& t = pose.translation();
  out += "\tX =";
  appendFixed(out, t.x(), kMmDecimals, 10);
  out += "  mm,\tY =";
  appendFixed(out, t.y(), kMmDecimals, 10);
  out += "  mm,\tZ =";
  appendFixed(out, t.z(), kMmDecimals, 10);
  out += "  mm,";
  out += kEol;
  const FanucWpr wpr = fanucWprFromRotation(pose.linear());
  out += "\tW =";
  appendFixed(out, radToDeg(wpr.w), kDegDecimals, 11);
  out += " deg,\tP =";
  appendFixed(out, radToDeg(wpr.p), kDegDecimals, 11);
  out += " deg,\tR =";
  appendFixed(out, radToDeg(wpr.r), kDegDecimals, 11);
  out += " deg";
  appendPositioner(out, externalDeg, frames);
  closePosition(out);
}

void appendJointPosition(std::string& out, size_t index, const std::array<double, 6>& jointsDeg,
                         const std::array<double, 2>& externalDeg, const TpPositionFrames& frames)
{
  openPosition(out, index);
  appendFrames(out, frames);
  out += kEol;
  for (size_t k = 0; k < 6; ++k) {
    out += k == 3 ? std::string(",") + kEol + "\t" : std::string(k == 0 ? "\t" : ",\t");
    out += "J" + std::to_string(k + 1) + "=";
    appendFixed(out, jointsDeg[k], kDegDecimals, 11);
    out += " deg";
  }
  appendPositioner(out, externalDeg, frames);
  closePosition(out);
}

bool isValidTpConfig(const std::string& config)
{
  size_t i = 0;
  auto skipSpaces = [&] {
    while (i < config.size() && config[i] == ' ') ++i;
  };
  auto letter = [&](char a, char b) {
    skipSpaces();
    if (i < config.size() && (config[i] == a || config[i] == b)) {
      ++i;
      return true;
    }
    return false;
  };
  auto integer = [&] {
    skipSpaces();
    if (i < config.size() && (config[i] == '-' || config[i] == '+')) ++i;
    const size_t start = i;
    while (i < config.size() && std::isdigit(static_cast<unsigned char>(config[i]))) ++i;
    return i > start;
  };
  auto comma = [&] {
    skipSpaces();
    if (i < config.size() && config[i] == ',') {
      ++i;
      return true;
    }
    return false;
  };
  if (!letter('N', 'F') || !letter('U', 'D') || !letter('T', 'B')) return false;
  for (int k = 0; k < 3; ++k)
    if (!comma() || !integer()) return false;
  skipSpaces();
  return i == config.size();
}

}  // namespace spira
