#include "spira/planning/crotch_flags.h"

#include <algorithm>
#include <cmath>

#include "spira/base/number_text.h"

namespace spira {

std::vector<CrotchFlags> flagsAtCrotches(const PlanOutput& plan, double beadWidth, double radius)
{
  std::vector<CrotchFlags> crotches;
  if (!plan.branching) return crotches;
  if (!(radius > 0.0)) radius = 4.0 * beadWidth;
  for (const BranchSaddle& saddle : plan.branching->saddles) {
    CrotchFlags c;
    c.crotch = saddle.position;
    for (const DepositFlag& f : plan.deposits.flags) {
      if ((f.position - c.crotch).norm() > radius) continue;
      ++c.flagged;
      if (f.kind == DepositDefect::Unsupported)
        ++c.midAir;
      else if (f.kind == DepositDefect::Thick && std::isfinite(f.height))
        c.thickest = std::max(c.thickest, f.height);
    }
    if (c.flagged > 0) crotches.push_back(c);
  }
  return crotches;
}

std::string crotchText(const std::vector<CrotchFlags>& crotches, size_t flaggedInAll, double hMax)
{
  std::string t;
  for (const CrotchFlags& c : crotches) {
    if (!t.empty()) t += "; ";
    t += std::to_string(c.flagged) + " of the " + std::to_string(flaggedInAll) +
         " flagged points lie around the junction's crotch at " + pointText(c.crotch, 1) + " mm";
    std::string what;
    if (c.thickest > 0.0)
      what = "the rings that cross it lie up to " + fixedText(c.thickest, 2) +
             " mm apart along the wall (h_max " + fixedText(hMax, 2) + " mm)";
    if (c.midAir > 0)
      what +=
          (what.empty() ? "" : " and ") + std::to_string(c.midAir) + " point(s) lie over the hollow under it";
    if (!what.empty()) t += ": it is a saddle of the part's height, level across its top, so " + what;
  }
  if (!t.empty())
    t += "; Spira lays every bead on the one below, which the level top of a crotch does not allow";
  return t;
}

}  // namespace spira
