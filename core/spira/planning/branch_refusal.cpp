#include "spira/planning/branch_refusal.h"

#include <algorithm>
#include <sstream>

#include "spira/base/error.h"
#include "spira/base/number_text.h"

namespace spira {

namespace {

std::string mmText(double v)
{
  return fixedText(v, 1) + " mm";
}

constexpr double kPi = 3.14159265358979323846;

}  // namespace

void refuseUnbranchedPart(const std::vector<BoundaryLoop>& loops, double minPerimeter, double beadWidth)
{
  std::ostringstream narrow;
  double shortest = 0.0;
  int count = 0;
  for (size_t i = 0; i < loops.size(); ++i) {
    if (loops[i].length >= minPerimeter) continue;
    narrow << (count ? ", " : "") << "free edge " << i + 1 << " is " << mmText(loops[i].length) << " around";
    shortest = count ? std::min(shortest, loops[i].length) : loops[i].length;
    ++count;
  }
  const std::string edges = std::to_string(loops.size()) + " free edges";
  if (count > 0) {
    std::ostringstream what, hint;
    what << "the part cannot be planned: it has " << edges
         << " but its walls do not part into branches a bead can lay: " << narrow.str()
         << ", shorter than one bead ring (" << mmText(minPerimeter) << ", pi x the " << mmText(beadWidth)
         << " bead width), so the branches there are narrower than the bead";
    hint << "use a bead narrower than " << mmText(shortest / kPi)
         << " (--bead-width) for these edges, and narrower still where the part narrows between them, or "
            "scale the part up in the CAD tool (check --unit if it should be larger): Spira lays a branch "
            "only where its wall is at least one bead ring around";
    throw InputError(what.str(), hint.str());
  }
  throw InputError("the part cannot be planned: it has " + edges +
                       " but its walls do not part into branches: at least one free edge is a hole in a "
                       "wall, or a branch narrows below one bead ring (" +
                       mmText(minPerimeter) + ") on its way to its free edge",
                   "close the hole(s) in the CAD or mesh tool ('spira-cli info' lists the loops and their "
                   "heights), or use a narrower bead (--bead-width) if a branch is that slender: Spira "
                   "plans walls with one free edge on the substrate, at most one on top, and one more per "
                   "branch");
}

void refuseUnsplitBranch(const std::string& role, size_t freeEdges, double minPerimeter)
{
  throw InputError(
      role + " of the multi-branch part keeps " + std::to_string(freeEdges) +
          " free edges: one of its branches narrows below one bead ring (" + mmText(minPerimeter) +
          ") between the junction and its free edge, so it could not be split off and laid as a "
          "branch of its own",
      "use a narrower bead (--bead-width) or scale the part up in the CAD tool (check --unit if it "
      "should be larger): Spira lays a branch only where its wall is at least one bead ring around");
}

}  // namespace spira
