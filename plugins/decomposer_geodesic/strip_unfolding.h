#pragma once

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "submesh_geodesics.h"

namespace spira::geodesic {

// The mesh as the unfolding needs it: vertex positions, and the vertices facing an edge (the
// third vertex of each face on it, -1 where there is no face).
struct StripMesh {
  std::function<Vec3(int)> position;
  std::function<std::array<int, 2>(int, int)> opposite;
};

// A stretch of path as the straight line of its unfolded strip. `run` is a stretch of a path:
// its two ends stay, every point between lies on an edge (vertices {a, b, -1}). The edges are laid
// out flat triangle by triangle (where two consecutive crossings sit on edges of no common face,
// as when CGAL puts them at edge ends, the edge of the face between is crossed too and a point is
// added for it) and each crossing is put where the straight line from the first point to the last
// meets its edge. nullopt when the edges do not form a strip, an end is not in the strip's end
// face, or the line leaves the strip (the path has to bend at a vertex there).
std::optional<std::vector<PathPoint>> straightRun(const std::vector<PathPoint>& run, const StripMesh& mesh);

}  // namespace spira::geodesic
