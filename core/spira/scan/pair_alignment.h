#pragma once

#include <string>
#include <vector>

#include "spira/base/transform.h"

namespace spira {

// A point of the part and the same place picked on the scan: the user's starting guess for a scan
// taken far from the part's frame, where ICP from the identity would lock onto the wrong surface.
struct PointPair {
  Vec3 part = Vec3::Zero();
  Vec3 scan = Vec3::Zero();
};

struct PairFit {
  Transform T_part_scan = Transform::Identity();  // the rigid motion taking the scan points onto the part's
  std::vector<double> residualsMm;                // per pair, after the fit
  double rmsMm = 0.0;
};

// The least-squares rigid motion (no scaling: scan and part are both mm) over three or more pairs
// (Umeyama). Throws InputError for fewer than three pairs, pairs whose points on either side are
// nearly collinear (the turn about their line is then free), or pairs that no rigid motion matches to
// within `toleranceMm` (a pair picked at the wrong place; the message names the worst one).
PairFit fitPointPairs(const std::vector<PointPair>& pairs, double toleranceMm);

// Pairs from text: one pair per line, "part_x,part_y,part_z,scan_x,scan_y,scan_z" (commas, spaces or
// tabs between numbers); blank lines, '#' comments and a header line of names are skipped. Throws
// InputError naming `what` and the line.
std::vector<PointPair> parsePointPairs(const std::string& text, const std::string& what);

}  // namespace spira
