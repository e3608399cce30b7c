#include "spira/base/number_text.h"

#include <charconv>
#include <iomanip>
#include <sstream>

namespace spira {

void appendNumber(std::string& out, double x)
{
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, r.ptr);
}

void appendNumber(std::string& out, long long x)
{
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, r.ptr);
}

std::string fixedText(double x, int digits)
{
  std::ostringstream o;
  o << std::fixed << std::setprecision(digits) << x;
  return o.str();
}

std::string significantText(double x, int digits)
{
  std::ostringstream o;
  o << std::setprecision(digits) << x;
  return o.str();
}

std::string pointText(const Vec3& p, int digits)
{
  return "(" + fixedText(p.x(), digits) + ", " + fixedText(p.y(), digits) + ", " + fixedText(p.z(), digits) +
         ")";
}

}  // namespace spira
