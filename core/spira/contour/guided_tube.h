#pragma once

#include <functional>
#include <vector>

#include "spira/contour/constant_distance.h"

namespace spira {

// A tube swept along a guide curve g(t) with a circular profile of radius A(t) (004_bd0df31205c0c3c0.txt
// Eq. 2.22-2.25): S(t, v) = g(t) + A(t) (cos v N(t) + sin v B(t)). N and B turn with the guide without
// twisting about it (a parallel-transported frame, sampled at `samples` values of t and interpolated), so a
// generatrix v stays on the same side of a bent tube. Throws InputError for t1 <= t0, a guide that stops
// (zero tangent) or fewer than 16 samples.
TubeSurface guidedTube(std::function<Vec3(double)> guide, std::function<double(double)> radius, double t0,
                       double t1, int samples = 4096);

// A guide through the points of a polyline (a tube's centre line, from its skeleton or a user's CSV):
// a centripetal Catmull-Rom curve, C1 so that the frame does not jump at the points, with t the
// chordal length from the first point (0 .. the polyline's length). Past either end it runs on along
// the end's tangent, so a tube can be followed beyond its nominal end. Throws InputError for fewer
// than 2 points or repeated consecutive points.
std::function<Vec3(double)> polylineGuide(std::vector<Vec3> points);

// The length of the guide between t0 and t1, by `samples` chords.
double guideLength(const std::function<Vec3(double)>& guide, double t0, double t1, int samples = 4096);

}  // namespace spira
