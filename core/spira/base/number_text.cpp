#include "spira/base/number_text.h"

#include <charconv>
#include <cmath>
#include <iomanip>
#include <limits>
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

double roundedTo(double x, int decimals)
{
  const double scale = std::pow(10.0, decimals);
  return std::round(x * scale) / scale;
}

std::string roundedText(double x, int decimals)
{
  std::string out;
  appendNumber(out, roundedTo(x, decimals) + 0.0);  // + 0.0: -0 reads "0"
  return out;
}

std::string pointText(const Vec3& p, int digits)
{
  return "(" + fixedText(p.x(), digits) + ", " + fixedText(p.y(), digits) + ", " + fixedText(p.z(), digits) +
         ")";
}

namespace {

template <class T>
std::optional<T> parseAll(std::string_view text, std::string& problem, const char* kind, const char* range)
{
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);  // from_chars rejects '+'
  T value{};
  const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  if (r.ec == std::errc::result_out_of_range) {
    problem = std::string("is beyond the range of ") + range;
    return std::nullopt;
  }
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || text.empty()) {
    problem = std::string("is not ") + kind;
    return std::nullopt;
  }
  return value;
}

}  // namespace

std::optional<double> parseFiniteNumber(std::string_view text, std::string& problem)
{
  const auto x = parseAll<double>(text, problem, "a number", "a double (about 1.8e308)");
  if (x && !std::isfinite(*x)) {
    problem = "is not a finite number";
    return std::nullopt;
  }
  return x;
}

std::optional<long long> parseWholeNumber(std::string_view text, std::string& problem)
{
  return parseAll<long long>(text, problem, "a whole number", "a 64-bit whole number");
}

std::string clippedText(std::string_view text)
{
  constexpr size_t kQuoteChars = 60;
  return text.size() <= kQuoteChars ? std::string(text) : std::string(text.substr(0, kQuoteChars)) + "...";
}

std::optional<double> parseMeshNumber(std::string_view text)
{
  std::string_view digits = text;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);  // from_chars rejects '+'
  double value = 0.0;
  const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || r.ec == std::errc::invalid_argument || r.ptr != digits.data() + digits.size())
    return std::nullopt;
  if (r.ec == std::errc::result_out_of_range) {
    const size_t e = digits.find_first_of("eE");
    const bool tiny = e != std::string_view::npos && digits.find('-', e) != std::string_view::npos;
    const double inf = std::numeric_limits<double>::infinity();
    value = tiny ? 0.0 : (digits.front() == '-' ? -inf : inf);
  }
  return value;
}

}  // namespace spira
