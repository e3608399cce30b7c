#include "exact_diff.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <sstream>

#include "support/test_support.h"

namespace spira::test {

namespace {

// Bitwise: 0.0 and -0.0 differ, and a NaN equals a NaN with the same payload.
bool same(double a, double b)
{
  return std::memcmp(&a, &b, sizeof a) == 0;
}

bool same(const Vec3& a, const Vec3& b)
{
  return same(a.x(), b.x()) && same(a.y(), b.y()) && same(a.z(), b.z());
}

std::string text(const Vec3& v)
{
  std::ostringstream s;
  s.precision(17);
  s << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return s.str();
}

std::string text(double v)
{
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// The first channel of two points that differs, as "name a vs b"; empty when none does.
std::string pointDifference(const TrajectoryPoint& a, const TrajectoryPoint& b)
{
  const std::pair<const char*, std::pair<Vec3, Vec3>> vectors[] = {{"position", {a.position, b.position}},
                                                                   {"normal", {a.normal, b.normal}},
                                                                   {"tangent", {a.tangent, b.tangent}},
                                                                   {"build", {a.build, b.build}}};
  for (const auto& [name, v] : vectors)
    if (!same(v.first, v.second)) return std::string(name) + " " + text(v.first) + " vs " + text(v.second);
  const std::pair<const char*, std::pair<double, double>> scalars[] = {
      {"height", {a.height, b.height}},
      {"travel speed", {a.travelSpeed, b.travelSpeed}},
      {"wire feed", {a.wireFeed, b.wireFeed}}};
  for (const auto& [name, v] : scalars)
    if (!same(v.first, v.second)) return std::string(name) + " " + text(v.first) + " vs " + text(v.second);
  const std::pair<const char*, std::pair<int, int>> integers[] = {
      {"path", {a.path, b.path}},
      {"revolution", {a.revolution, b.revolution}},
      {"generatrix", {a.generatrix, b.generatrix}},
      {"arc", {a.arcOn, b.arcOn}}};
  for (const auto& [name, v] : integers)
    if (v.first != v.second)
      return std::string(name) + " " + std::to_string(v.first) + " vs " + std::to_string(v.second);
  return {};
}

}  // namespace

std::string trajectoryDifference(const Trajectory& a, const Trajectory& b)
{
  std::ostringstream out;
  if (a.size() != b.size()) out << a.size() << " points vs " << b.size() << "; ";
  size_t differing = 0, first = 0;
  std::string firstWhat;
  double largest = 0.0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    const std::string what = pointDifference(a.points[i], b.points[i]);
    if (what.empty()) continue;
    if (differing++ == 0) {
      first = i;
      firstWhat = what;
    }
    largest = std::max(largest, (a.points[i].position - b.points[i].position).norm());
  }
  if (differing)
    out << differing << " point(s) differ, first point " << first << " (revolution "
        << a.points[first].revolution << "): " << firstWhat << "; largest position difference "
        << text(largest) << " mm; ";
  std::set<std::string> names;
  for (const auto& [name, values] : a.extra) names.insert(name);
  for (const auto& [name, values] : b.extra) names.insert(name);
  for (const std::string& name : names) {
    const auto ia = a.extra.find(name), ib = b.extra.find(name);
    if (ia == a.extra.end() || ib == b.extra.end()) {
      out << "channel " << name << " in one trajectory only; ";
      continue;
    }
    const auto& va = ia->second;
    const auto& vb = ib->second;
    const bool equal = va.size() == vb.size() && std::equal(va.begin(), va.end(), vb.begin(),
                                                            [](double x, double y) { return same(x, y); });
    if (!equal) out << "channel " << name << " differs; ";
  }
  return out.str();
}

std::string fieldDifference(const std::vector<double>& a, const std::vector<double>& b)
{
  if (a.size() != b.size()) return std::to_string(a.size()) + " values vs " + std::to_string(b.size());
  size_t differing = 0;
  double largest = 0.0;
  for (size_t v = 0; v < a.size(); ++v)
    if (!same(a[v], b[v])) {
      ++differing;
      largest = std::max(largest, std::abs(a[v] - b[v]));
    }
  if (!differing) return {};
  return std::to_string(differing) + " of " + std::to_string(a.size()) + " values differ, by up to " +
         text(largest);
}

std::string generatricesDifference(const Generatrices& a, const Generatrices& b)
{
  std::ostringstream out;
  if (a.lines.size() != b.lines.size()) {
    out << a.lines.size() << " generatrices vs " << b.lines.size();
    return out.str();
  }
  size_t differing = 0;
  double largest = 0.0;
  for (size_t g = 0; g < a.lines.size(); ++g) {
    const Polyline &la = a.lines[g], &lb = b.lines[g];
    bool equal = la.size() == lb.size();
    for (size_t k = 0; equal && k < la.size(); ++k) equal = same(la[k], lb[k]);
    if (equal) continue;
    ++differing;
    for (size_t k = 0; k < std::min(la.size(), lb.size()); ++k)
      largest = std::max(largest, (la[k] - lb[k]).norm());
  }
  if (differing)
    out << differing << " of " << a.lines.size() << " generatrices differ (largest point difference "
        << text(largest) << " mm)";
  bool normalsEqual = a.normals.size() == b.normals.size();
  for (size_t g = 0; normalsEqual && g < a.normals.size(); ++g) {
    normalsEqual = a.normals[g].size() == b.normals[g].size();
    for (size_t k = 0; normalsEqual && k < a.normals[g].size(); ++k)
      normalsEqual = same(a.normals[g][k], b.normals[g][k]);
  }
  if (!normalsEqual) out << (differing ? "; " : "") << "their normals differ";
  if (a.hasClosurePoint != b.hasClosurePoint || !same(a.closurePoint, b.closurePoint))
    out << "; closure point " << text(a.closurePoint) << " vs " << text(b.closurePoint);
  return out.str();
}

std::string folderDifference(const std::filesystem::path& a, const std::filesystem::path& b,
                             const std::vector<std::string>& skip)
{
  const auto names = [&](const std::filesystem::path& dir) {
    std::set<std::string> out;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (std::find(skip.begin(), skip.end(), entry.path().filename().string()) == skip.end())
        out.insert(entry.path().filename().string());
    return out;
  };
  const std::set<std::string> na = names(a), nb = names(b);
  std::ostringstream out;
  if (na != nb) {
    out << "the folders hold different files:";
    for (const auto& n : na) out << " " << n;
    out << " vs";
    for (const auto& n : nb) out << " " << n;
    return out.str();
  }
  for (const std::string& name : na) {
    const std::string ta = readBytes(a / name), tb = readBytes(b / name);
    if (ta == tb) continue;
    std::istringstream la(ta), lb(tb);
    std::string x, y;
    for (size_t line = 1;; ++line) {
      const bool hasX = static_cast<bool>(std::getline(la, x)), hasY = static_cast<bool>(std::getline(lb, y));
      if (!hasX && !hasY) break;
      if (hasX && hasY && x == y) continue;
      out << name << " differs from line " << line << ": '" << (hasX ? x : "<end>") << "' vs '"
          << (hasY ? y : "<end>") << "'; ";
      break;
    }
  }
  return out.str();
}

}  // namespace spira::test
