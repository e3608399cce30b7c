#pragma once

#include <vector>

#include "spira/contour/iso_contour.h"
#include "spira/contour/surface_point.h"

namespace spira {

// Length of a polyline, closing segment included when `closed`.
double polylineLength(const std::vector<Vec3>& points, bool closed);

// Vector area of a closed polygon, 1/2 sum p_i x p_(i+1). Its component along a unit axis is the
// signed area of the polygon projected on the plane normal to the axis: positive when the polygon
// runs counter-clockwise seen from the tip of the axis. Independent of the origin.
Vec3 vectorArea(const std::vector<Vec3>& loop);

// Whether the loop runs counter-clockwise about `axis` (seen from its tip).
bool isCounterClockwise(const IsoContour& loop, const Vec3& axis);
// Reverses the loop if needed so that it runs counter-clockwise about `axis`; returns whether it
// did. Extraction already orients every contour by the field (higher values on the left, seen
// from outside), which is the robust rule on any shape; this axis rule is for callers that need a
// fixed turning sense about a known axis, e.g. a part standing on +Z.
bool orientCounterClockwise(IsoContour& loop, const Vec3& axis);

// A closed contour resampled to n points equally spaced in arc length along it.
//
// Why piecewise-linear arc-length resampling rather than the thesis's B-spline fit: the contour's
// vertices lie exactly on the mesh surface and its segments inside faces, so a linear resample
// stays on the surface and keeps a face and barycentric weights for every point (normals and
// other per-vertex values are interpolated exactly there). A spline through the same points would
// cut corners and leave the surface by up to its sagitta, and could overshoot where points are
// uneven. The contour is dense (one point per crossed edge), so the polygon is already as faithful
// to the surface as the mesh itself: the only error left is the mesh's own chordal error.
struct ResampledLoop {
  double level = 0.0;
  double length = 0.0;  // of the contour, mm (so spacing = length / points.size())
  std::vector<SurfacePoint> points;
  std::vector<Vec3> positions() const;
};

// Arc-length position (from points[0], along the contour's direction, in [0, length)) of the
// point of the closed contour nearest to q.
double nearestArcParameter(const IsoContour& loop, const Vec3& q);

// Resamples the closed contour to n points, the first at arc length `startArc` from points[0],
// the k-th at startArc + k * length / n. Throws InputError for an open contour or n < 3.
ResampledLoop resampleLoop(const TriangleMesh& mesh, const IsoContour& loop, size_t n, double startArc = 0.0);

// Phase alignment: the resampling whose first point is the point of the contour nearest to
// `previousStart` (typically the first point of the previous contour), so that consecutive
// contours start side by side.
ResampledLoop resampleLoopContinuing(const TriangleMesh& mesh, const IsoContour& loop, size_t n,
                                     const Vec3& previousStart);

// Index of the point nearest to q (lowest index on ties).
size_t nearestIndex(const std::vector<SurfacePoint>& points, const Vec3& q);

}  // namespace spira
