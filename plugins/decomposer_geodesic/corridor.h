#pragma once

#include <cstdint>
#include <vector>

#include "geodesic_mesh.h"

namespace spira::geodesic {

// A band of faces around a guide trace, in which an exact geodesic is searched: exact search
// costs grow faster than the face count, so each generatrix gets its own narrow band instead of
// the whole mesh. Reusable scratch (one per thread): marks are cleared by bumping a stamp.
class Corridor {
 public:
  explicit Corridor(const GeodesicMesh& mesh);

  // The `seed` faces and `rings` rings of faces around them (each ring adds the faces across the
  // band's edges: sharing vertices instead would swallow the whole fan of a high-valence vertex,
  // such as the pole of a dome), then the faces around any vertex where the band would meet
  // itself through that vertex only (two separate fans: not a surface an exact search can walk).
  void build(const std::vector<int>& seed, int rings);
  void buildWholeMesh();
  // Adds the faces around `vertices` (where the band met itself through a single vertex).
  void addStars(const std::vector<int>& vertices);

  const std::vector<int>& faces() const { return faces_; }
  const std::vector<int>& vertices() const { return vertices_; }
  bool wholeMesh() const { return whole_; }
  bool containsFace(int f) const { return faceStamp_[size_t(f)] == stamp_; }
  bool containsVertex(int v) const { return vertexStamp_[size_t(v)] == stamp_; }
  // Whether the band was cut out of the mesh at vertex v: some face around v is not in it. A
  // shortest path in the band that passes through such a vertex may be longer than on the mesh.
  bool isCut(int v) const;

 private:
  void reset();
  void addFace(int f);
  // Faces of the band around v that follow, turning about v, a face outside the band.
  int fanStarts(int v) const;
  void closeFans();

  const GeodesicMesh* mesh_;
  std::vector<std::uint32_t> faceStamp_, vertexStamp_;
  std::uint32_t stamp_ = 0;
  std::vector<int> faces_, vertices_;
  bool whole_ = false;
};

}  // namespace spira::geodesic
