#include "tube_centre_line.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/contour/iso_contour.h"

namespace spira {
namespace {

std::string pointText(const Vec3& p)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

}  // namespace

double loopRadius(const TriangleMesh& mesh, const BoundaryLoop& loop)
{
  const Vec3 c = loopCentroid(mesh, loop);
  double sum = 0.0;
  for (int v : loop.vertices) sum += (mesh.vertices[size_t(v)] - c).norm();
  return loop.vertices.empty() ? 0.0 : sum / double(loop.vertices.size());
}

Polyline centreLineFromField(const TriangleMesh& mesh, const std::vector<double>& field,
                             const BoundaryLoop& lower, const BoundaryLoop& upper, int levels)
{
  std::vector<double> values;
  for (int k = 1; k < levels; ++k) values.push_back(double(k) / levels);
  const std::vector<IsoLevel> contours = extractIsoContours(mesh, field, values);
  Polyline line{loopCentroid(mesh, lower)};
  for (const IsoLevel& level : contours) {
    if (level.contours.empty()) continue;
    const double longest = level.contours.front().length();
    std::vector<Vec3> centres;
    for (const IsoContour& c : level.contours)
      if (c.closed && c.length() > 0.2 * longest) centres.push_back(polygonCentroid(c.positions()));
    if (centres.size() > 1 || !level.contours.front().closed) {
      std::string where;
      for (const Vec3& c : centres) where += (where.empty() ? "" : " and ") + pointText(c);
      throw InputError(
          "the part is not one tube: at " + std::to_string(int(100 * level.value + 0.5)) +
              " % of the way from its lower edge to its upper one its surface parts into " +
              std::to_string(level.contours.size()) + " loops" +
              (where.empty() ? "" : " (around " + where + ")"),
          "plan a branching part with --strategy isovalue, which splits it into tubes, or give the tube's "
          "centre line with --guide FILE");
    }
    line.push_back(centres.front());
  }
  line.push_back(loopCentroid(mesh, upper));
  Polyline distinct{line.front()};
  for (const Vec3& p : line)
    if ((p - distinct.back()).norm() > 1e-6) distinct.push_back(p);
  return distinct;
}

Polyline readGuideCsv(const std::string& path)
{
  // A named pipe or a device never reaches a stream: readFile refuses anything but a regular file.
  std::istringstream in(readFile(path));
  Polyline line;
  std::string text;
  int number = 0;
  while (std::getline(in, text)) {
    ++number;
    if (const auto hash = text.find('#'); hash != std::string::npos) text.erase(hash);
    for (char& c : text)
      if (c == ',' || c == ';' || c == '\t' || c == '\r') c = ' ';
    std::istringstream fields(text);
    std::vector<std::string> words;
    for (std::string w; fields >> w;) words.push_back(w);
    if (words.empty()) continue;
    std::vector<double> xyz;
    std::string problem;
    for (const std::string& w : words)
      if (const auto x = parseFiniteNumber(w, problem)) xyz.push_back(*x);
    if (xyz.empty() && line.empty() && number == 1) continue;  // a header
    if (xyz.size() != 3 || words.size() != 3)
      throw InputError(path + " line " + std::to_string(number) +
                           ": expected three numbers x, y, z (mm), found '" + text.substr(0, 60) + "'",
                       "write one guide point per line as x,y,z");
    const Vec3 p(xyz[0], xyz[1], xyz[2]);
    if (line.empty() || (p - line.back()).norm() > 1e-9) line.push_back(p);
  }
  if (line.size() < 2)
    throw InputError(path + " holds " + std::to_string(line.size()) + " distinct guide point(s)",
                     "give the tube's centre line as at least 2 points, base end first");
  return line;
}

}  // namespace spira
