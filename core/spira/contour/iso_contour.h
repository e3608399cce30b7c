#pragma once

#include <vector>

#include "spira/base/progress.h"
#include "spira/contour/surface_point.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// Where an iso-line crosses a mesh edge: position = (1 - t) x[v0] + t x[v1], with the field below
// the level at v0 and at or above it at v1, 0 < t < 1. A point on a vertex (field exactly at the
// level, or the vertex of a boundary loop) has v0 == v1 == that vertex and t = 0.
struct ContourPoint {
  Vec3 position = Vec3::Zero();
  int v0 = -1, v1 = -1;
  double t = 0.0;
  bool onVertex() const { return v0 == v1; }
};

// One connected component of an iso-line: a closed loop, or an open polyline whose ends lie on
// free edges. Segment i runs from points[i] to points[i + 1] (to points[0] for the closing segment
// of a loop) inside face segmentFaces[i], so any point of it can be located on the surface.
//
// Orientation: a contour runs with the higher field values on its left, seen from the side the
// face normals point to (outside). On an outward-facing part standing on +Z with a field growing
// upwards that is counter-clockwise seen from above, the direction of the lower boundary loop.
struct IsoContour {
  double level = 0.0;
  bool closed = true;
  std::vector<ContourPoint> points;  // consecutive points are distinct
  std::vector<int> segmentFaces;     // points.size() entries for a loop, one fewer for a polyline

  size_t segmentCount() const { return segmentFaces.size(); }
  double length() const;  // mm, closing segment included for a loop
  std::vector<Vec3> positions() const;
  // points[i] located in the face of the segment leaving it (the one entering it for the last
  // point of a polyline).
  SurfacePoint surfacePoint(const TriangleMesh& mesh, size_t i) const;
  // Barycentric weights of points[i] in `face`, a face holding its edge (or vertex).
  Vec3 barycentricIn(const TriangleMesh& mesh, size_t i, int face) const;
  void reverse();
};

// The contours of one level, longest first.
struct IsoLevel {
  double value = 0.0;
  std::vector<IsoContour> contours;
};

// Marching triangles. Signs are taken as field >= level (a symbolic perturbation of the level
// downwards), so a vertex exactly at the level counts as above it: every edge then holds at most
// one crossing, every crossing edge is shared by at most two crossed faces and contours come out
// as clean curves even through vertices at the level; the resulting zero-length pieces are
// merged so consecutive points stay distinct. A level at or below the field minimum gives no
// contour; a level equal to a local maximum gives none either (the loop shrinks to the vertex).
//
// `levels` must be sorted ascending. Each face is visited only for the levels its field range
// spans; levels run in parallel (TBB). Throws InputError when the field does not have one finite
// value per vertex, or at a non-manifold edge (three faces crossing on one edge); honours
// cancellation through `progress`.
std::vector<IsoLevel> extractIsoContours(const TriangleMesh& mesh, const std::vector<double>& field,
                                         const std::vector<double>& levels, Progress* progress = nullptr);
IsoLevel extractIsoContour(const TriangleMesh& mesh, const std::vector<double>& field, double level);

// A boundary loop (vertex ids in order, first not repeated) as a closed contour at `level`.
// `meshOnLeft`: orient it with the mesh on its left seen from outside, as a lower edge is (the
// field grows into the mesh); false for an upper edge, where the field grows away from it, so the
// result runs like the iso-contours next to it. Throws InputError when two consecutive loop
// vertices share no boundary face.
IsoContour contourFromBoundaryLoop(const TriangleMesh& mesh, const std::vector<int>& loopVertices,
                                   double level, bool meshOnLeft);

}  // namespace spira
