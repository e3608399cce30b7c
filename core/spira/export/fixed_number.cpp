#include "spira/export/fixed_number.h"

#include <charconv>
#include <cmath>

namespace spira {

void appendFixed(std::string& out, double x, int decimals, int width)
{
  char buf[400];  // fixed notation of the largest double needs 309 digits before the point
  const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::fixed, decimals);
  const char* begin = buf;
  if (buf[0] == '-') {
    bool allZero = true;
    for (const char* p = buf + 1; p < r.ptr; ++p)
      if (*p != '0' && *p != '.') allZero = false;
    if (allZero) ++begin;  // -0.0004 at 3 decimals reads "0.000", not "-0.000"
  }
  const size_t length = static_cast<size_t>(r.ptr - begin);
  if (width > 0 && length < static_cast<size_t>(width)) out.append(static_cast<size_t>(width) - length, ' ');
  out.append(begin, length);
}

}  // namespace spira
