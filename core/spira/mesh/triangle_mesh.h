#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "spira/base/transform.h"

namespace spira {

struct BoundingBox {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());
  bool empty() const { return !(min.x() <= max.x()); }
  void extend(const Vec3& p)
  {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  Vec3 size() const { return empty() ? Vec3::Zero() : Vec3(max - min); }
  Vec3 center() const { return empty() ? Vec3::Zero() : Vec3(0.5 * (min + max)); }
  double diagonal() const { return size().norm(); }
};

// Bounding box of the finite points among points[0..count) (NaN or infinite ones are skipped).
BoundingBox finiteBounds(const Vec3* points, size_t count);

using Face = std::array<int, 3>;

// An indexed triangle mesh in millimetres. Faces are counter-clockwise seen from outside
// (outward normals), as the STL convention asks. The mesh is a plain value: algorithms take
// it by const reference and never keep pointers into it.
struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<Face> faces;

  size_t vertexCount() const { return vertices.size(); }
  size_t faceCount() const { return faces.size(); }
  bool empty() const { return faces.empty(); }

  BoundingBox bounds() const;  // of the finite vertices (a NaN vertex would poison the box)
  // Unnormalised face normal (length = 2 * area).
  Vec3 faceNormalScaled(size_t f) const;
  Vec3 faceNormal(size_t f) const;
  double faceArea(size_t f) const;
  double area() const;
  double meanEdgeLength() const;  // each undirected edge counted once
  // Area-weighted vertex normals (unit length; zero for isolated vertices).
  std::vector<Vec3> vertexNormals() const;

  // Maps every vertex through T (mm). A mirroring T also reverses the faces, so normals stay outward.
  void transform(const Transform& T);
  TriangleMesh transformed(const Transform& T) const;

  bool operator==(const TriangleMesh& o) const { return vertices == o.vertices && faces == o.faces; }
  bool operator!=(const TriangleMesh& o) const { return !(*this == o); }
};

}  // namespace spira
