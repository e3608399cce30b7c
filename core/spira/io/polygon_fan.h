#pragma once

#include <string>
#include <vector>

#include "spira/mesh/triangle_mesh.h"

namespace spira {

// Faces a reader gets as corner loops (PLY, OBJ) become triangles fanned from the first corner, in
// file order; what was split or dropped is counted so that the user hears of it once.
struct PolygonFan {
  size_t polygonFaces = 0;     // loops of more than three corners, split into triangles
  size_t degenerateFaces = 0;  // loops of fewer than three corners, dropped

  void add(const std::vector<int>& loop, std::vector<Face>& faces);
  // One sentence naming `source` for each count that is not zero.
  void appendWarnings(const std::string& source, std::vector<std::string>& warnings) const;
};

}  // namespace spira
