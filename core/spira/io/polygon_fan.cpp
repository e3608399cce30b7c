#include "spira/io/polygon_fan.h"

namespace spira {

void PolygonFan::add(const std::vector<int>& loop, std::vector<Face>& faces)
{
  if (loop.size() < 3) {
    ++degenerateFaces;
    return;
  }
  if (loop.size() > 3) ++polygonFaces;
  for (size_t c = 1; c + 1 < loop.size(); ++c) faces.push_back({loop[0], loop[c], loop[c + 1]});
}

void PolygonFan::appendWarnings(const std::string& source, std::vector<std::string>& warnings) const
{
  const auto faces = [](size_t n) { return n == 1 ? std::string("1 face") : std::to_string(n) + " faces"; };
  if (polygonFaces > 0)
    warnings.push_back(faces(polygonFaces) + " in '" + source +
                       "' with more than three corners split into triangles");
  if (degenerateFaces > 0)
    warnings.push_back(faces(degenerateFaces) + " in '" + source + "' with fewer than three corners ignored");
}

}  // namespace spira
