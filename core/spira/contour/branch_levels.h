#pragma once

#include <vector>

#include "spira/base/progress.h"
#include "spira/contour/iso_contour.h"

namespace spira {

// What counts as a branch when the iso-contours of a field grown from the base are counted
// (thesis 000_dbb97c2716e10cc3.txt §3.4.3): a closed contour at least `minPerimeter` long. Shorter loops are
// a lone field extremum (mesh noise, the several maxima of a closure zone) or a wall narrower than the bead,
// which cannot be built as a branch of its own.
struct BranchScanOptions {
  double minPerimeter = 0.0;  // mm; <= 0: 3 mean edge lengths
  // Spacing of the scanned levels in field units; <= 0: the mean edge length times the field's
  // mean gradient (one level per ring of faces).
  double levelStep = 0.0;
  size_t maxLevels = 4000;
  // The split level is bisected until the bracket is narrower than this, in field units;
  // <= 0: 1e-9 of the field range.
  double tolerance = 0.0;
  // Saddle vertices below the scan's first event checked one by one (a branch can hide between
  // two scanned levels); more are left to the scan.
  size_t maxSaddleChecks = 256;
};

// Where the contour count of a field first changes, scanning up from `from`.
struct BranchSplit {
  bool found = false;      // the count goes from 1 to `branches` >= 2
  bool vanished = false;   // the contours ran into a free edge or ended (no split below `stopLevel`)
  double stopLevel = 0.0;  // first scanned level where the scan stopped (split or not)
  // The saddle: the highest level with one contour and the lowest with several bracket it, to
  // `tolerance`. `saddle` is their midpoint; the field there is a saddle vertex's value.
  double below = 0.0, above = 0.0, saddle = 0.0;
  int saddleVertex = -1;  // a vertex with several sign changes around it and its value in the bracket
  // The saddle vertex, or where the two longest contours at `above` come closest without one.
  Vec3 position = Vec3::Zero();
  size_t branches = 0;  // significant contours just above the saddle
  int bisections = 0;
};

// The closed contours of `level` at least `minPerimeter` long; `touchesEdge` is set when any
// contour (of any length) is open, i.e. runs into a free edge.
size_t significantContourCount(const IsoLevel& level, double minPerimeter, bool* touchesEdge = nullptr);

// Scans the levels of `field` above `from` (the base's highest value) for the first change of the
// significant contour count, checks the saddle vertices below it one by one, and bisects the
// first split found. The scan stops where the contours run into a free edge or vanish. Throws
// InputError when the field has the wrong size or non-finite values.
BranchSplit findFirstBranchSplit(const TriangleMesh& mesh, const std::vector<double>& field, double from,
                                 const BranchScanOptions& options, Progress& progress);

// The largest value of `field` on `vertices` (-infinity for none): where a scan from an edge starts.
double highestValueOn(const std::vector<int>& vertices, const std::vector<double>& field);

// The saddle vertices of the piecewise linear field with values in [lo, hi], by value: their
// one-ring changes side of their own value 4 times or more (equal values ordered by vertex id).
std::vector<int> saddleVertices(const TriangleMesh& mesh, const std::vector<double>& field, double lo,
                                double hi);

// A vertex whose one-ring changes side of its own value 4 times or more (a saddle of the piecewise
// linear field; equal values are ordered by vertex id) with value in [lo, hi], the closest to
// (lo + hi) / 2; -1 when there is none.
int saddleVertexIn(const TriangleMesh& mesh, const std::vector<double>& field, double lo, double hi);

}  // namespace spira
