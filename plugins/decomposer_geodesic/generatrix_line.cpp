#include "generatrix_line.h"

#include <algorithm>

#include "spira/base/error.h"
#include "spira/path/arc_length_polyline.h"

namespace spira::geodesic {

double GeneratrixLine::length() const
{
  double s = 0.0;
  for (size_t k = 1; k < points.size(); ++k) s += (points[k] - points[k - 1]).norm();
  return s;
}

GeneratrixLine resampleLine(const GeneratrixLine& line, size_t count)
{
  if (count < 2 || line.points.empty() || line.normals.size() != line.points.size())
    throw InternalError("resampleLine needs at least 2 samples and one normal per point");
  GeneratrixLine out;
  out.angle = line.angle;
  out.fillIn = line.fillIn;
  out.exactLength = line.exactLength;
  out.points.resize(count);
  out.normals.resize(count);
  if (line.points.size() == 1) {
    std::fill(out.points.begin(), out.points.end(), line.points[0]);
    std::fill(out.normals.begin(), out.normals.end(), line.normals[0]);
    return out;
  }
  const ArcLengthPolyline arc(line.points, line.normals);
  const double L = arc.length();
  size_t cursor = 0;
  for (size_t k = 0; k < count; ++k) {
    const ArcLengthPolyline::Sample s = arc.at(L * double(k) / double(count - 1), cursor);
    out.points[k] = s.position;
    out.normals[k] = s.normal;
  }
  out.points.front() = line.points.front();
  out.points.back() = line.points.back();
  out.normals.front() = line.normals.front();
  out.normals.back() = line.normals.back();
  return out;
}

}  // namespace spira::geodesic
