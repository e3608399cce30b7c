#include "spira/base/number_text.h"

#include <charconv>

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

}  // namespace spira
