#pragma once

#include "spira/base/transform.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// Axis-aligned box helpers for the broad phase (BoundingBox lives with the mesh type).

inline bool boxesOverlap(const BoundingBox& a, const BoundingBox& b)
{
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

// Gap between two boxes, 0 when they overlap: a cheap lower bound of the distance of their contents.
inline double boxDistance(const BoundingBox& a, const BoundingBox& b)
{
  const Vec3 gap = (a.min - b.max).cwiseMax(b.min - a.max).cwiseMax(0.0);
  return gap.norm();
}

inline BoundingBox inflated(const BoundingBox& box, double margin)
{
  BoundingBox out = box;
  out.min.array() -= margin;
  out.max.array() += margin;
  return out;
}

inline BoundingBox merged(const BoundingBox& a, const BoundingBox& b)
{
  BoundingBox out;
  out.min = a.min.cwiseMin(b.min);
  out.max = a.max.cwiseMax(b.max);
  return out;
}

// The axis-aligned box of `box` carried by T (exact for the box corners, hence conservative).
inline BoundingBox transformedBox(const BoundingBox& box, const Transform& T)
{
  const Vec3 center = T * box.center();
  const Vec3 half = T.linear().cwiseAbs() * (0.5 * box.size());
  BoundingBox out;
  out.min = center - half;
  out.max = center + half;
  return out;
}

}  // namespace spira
