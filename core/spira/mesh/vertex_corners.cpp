#include "spira/mesh/vertex_corners.h"

#include "spira/mesh/vertex_sort.h"

namespace spira {

VertexCorners buildVertexCorners(const TriangleMesh& mesh, const std::vector<std::uint8_t>* useFace)
{
  // Corners come out in increasing order already: the per-vertex sort only checks that.
  VertexSorted<int> sorted =
      sortByVertex<int>(mesh.faceCount(), mesh.vertexCount(), [&](size_t f, const auto& sink) {
        const Face& t = mesh.faces[f];
        if ((useFace != nullptr && (*useFace)[f] == 0) || hasRepeatedIndex(t)) return;
        for (int k = 0; k < 3; ++k) sink(t[k], static_cast<int>(3 * f + k));
      });
  return VertexCorners{std::move(sorted.offset), std::move(sorted.items)};
}

}  // namespace spira
