#include "spira/scan/pair_alignment.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "spira/base/error.h"
#include "spira/base/number_text.h"

namespace spira {

namespace {

// How far the points spread off their best line, relative to their extent: under this, three picks
// on one edge of a wall cannot fix the turn about that edge.
double collinearity(const std::vector<Vec3>& points)
{
  Vec3 centre = Vec3::Zero();
  for (const Vec3& p : points) centre += p;
  centre /= double(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points) scatter += (p - centre) * (p - centre).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter);
  const double largest = eig.eigenvalues()(2);
  return largest > 0.0 ? std::sqrt(std::max(0.0, eig.eigenvalues()(1)) / largest) : 0.0;
}

constexpr double kMinimumSpread = 0.05;

}  // namespace

PairFit fitPointPairs(const std::vector<PointPair>& pairs, double toleranceMm)
{
  if (pairs.size() < 3)
    throw InputError(
        "alignment by picked points needs three pairs, " + std::to_string(pairs.size()) + " given",
        "pick three or more places on the part and the same places on the scan");
  std::vector<Vec3> part, scan;
  for (const PointPair& p : pairs) part.push_back(p.part), scan.push_back(p.scan);
  for (const auto& [side, points] : {std::pair<const char*, const std::vector<Vec3>&>{"part", part},
                                     std::pair<const char*, const std::vector<Vec3>&>{"scan", scan}})
    if (collinearity(points) < kMinimumSpread)
      throw InputError(std::string("the picked points on the ") + side + " lie nearly on one line",
                       "pick three places far apart and not in a row, e.g. on two faces of the part");
  Eigen::Matrix3Xd src(3, pairs.size()), dst(3, pairs.size());
  for (size_t i = 0; i < pairs.size(); ++i)
    src.col(Eigen::Index(i)) = scan[i], dst.col(Eigen::Index(i)) = part[i];
  PairFit fit;
  fit.T_part_scan = Transform(Eigen::umeyama(src, dst, false));
  double sum = 0.0;
  size_t worst = 0;
  for (size_t i = 0; i < pairs.size(); ++i) {
    fit.residualsMm.push_back((fit.T_part_scan * scan[i] - part[i]).norm());
    sum += fit.residualsMm.back() * fit.residualsMm.back();
    if (fit.residualsMm[i] > fit.residualsMm[worst]) worst = i;
  }
  fit.rmsMm = std::sqrt(sum / double(pairs.size()));
  if (fit.residualsMm[worst] > toleranceMm)
    throw InputError("the picked pairs do not match by one rigid motion: pair " + std::to_string(worst + 1) +
                         " is " + significantText(fit.residualsMm[worst], 3) + " mm off after the best fit",
                     "pick pair " + std::to_string(worst + 1) +
                         " again at the same place on both, or check the scan's units");
  return fit;
}

std::vector<PointPair> parsePointPairs(const std::string& text, const std::string& what)
{
  std::vector<PointPair> pairs;
  std::istringstream in(text);
  std::string line;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    const std::string written = line;
    for (char& c : line)
      if (c == ',' || c == ';' || c == '\t' || c == '\r') c = ' ';
    std::istringstream fields(line);
    std::vector<double> v;
    std::string word;
    bool words = false;
    while (fields >> word) {
      char* end = nullptr;
      const double x = std::strtod(word.c_str(), &end);
      if (end == word.c_str() || *end != '\0' || !std::isfinite(x))
        words = true;
      else
        v.push_back(x);
    }
    if (v.empty() && !words) continue;
    if (words && v.empty() && pairs.empty()) continue;  // a header of column names
    if (words || v.size() != 6)
      throw InputError(what + ", line " + std::to_string(lineNo) + ": '" + written + "' is not six numbers",
                       "write one pair per line: part_x,part_y,part_z,scan_x,scan_y,scan_z (mm)");
    pairs.push_back({Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5])});
  }
  return pairs;
}

}  // namespace spira
