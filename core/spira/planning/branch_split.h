#pragma once

#include <vector>

#include "spira/base/progress.h"
#include "spira/mesh/mesh_report.h"

namespace spira {

// One mono-branch sub-part of a multi-branch part.
struct BranchPiece {
  TriangleMesh mesh;
  MeshReport report;          // validateMesh(mesh)
  int lowerLoop = -1;         // index into report.boundaryLoops of the edge it grows from
  std::vector<double> field;  // geodesic distance from the base of the piece it was cut from
  int parent = -1;            // the piece it stands on (-1: on the substrate)
  int depth = 0;              // number of splits below it
  double lowerLevel = 0.0;    // `field` on its lower edge (lowest value)
  // Geodesic distance from its lower edge down to the upper edge of the piece it stands on (the
  // junction gap it has to bridge), mm; 0 for the piece on the substrate.
  double supportGap = 0.0;
  double area = 0.0;   // mm^2
  bool trunk = false;  // the part below a split (or the whole part when nothing splits)
};

// A split of one piece: the saddle of its field and where it was cut.
struct BranchSaddle {
  int piece = -1;      // index of the trunk left below the saddle
  double level = 0.0;  // geodesic distance from the trunk's base to the saddle (bisected), mm
  int bisections = 0;
  Vec3 position = Vec3::Zero();  // the saddle vertex
  size_t branches = 0;
  double trunkTop = 0.0;    // cut level of the trunk's upper edge, in the smoothed field
  double branchBase = 0.0;  // cut level of the branches' lower edges, in the smoothed field
  double gapArea = 0.0;     // mm^2 of surface between the two cuts, left to the bead to bridge
};

struct BranchSplitOptions {
  double minPerimeter = 0.0;  // shortest contour counted as a branch (mm); <= 0: 3 mean edges
  // Height of the junction gap (mm of geodesic distance); <= 0 picks half the thinnest deposit, so
  // that a branch's first ring, laid h_min to h_max above the trunk's last, still lies on the branch.
  double junctionGap = 0.0;
  double nominalHeight = 2.0;    // h, mm
  double thinnestDeposit = 1.8;  // h_min, mm
  // The cuts follow the distance smoothed by one implicit heat step of time smoothing * h^2
  // (field_smoothing.h); 0 cuts the raw distance. The step only has to remove the distance's
  // face-to-face wobble; a longer one also rounds the crease the distance has at the crotch, so
  // the cut leaves the distance's level line there and the gap the branches bridge is no longer
  // the junction gap.
  double smoothing = 8.0;
  int maxDepth = 4;  // pieces deeper than this many splits are left whole
};

struct BranchDecomposition {
  std::vector<BranchPiece> pieces;  // build order: every piece after the one it stands on
  std::vector<BranchSaddle> saddles;
  std::vector<double> field;  // geodesic distance from the base over the input mesh
  double junctionGap = 0.0;   // mm, as used
  double minPerimeter = 0.0;  // mm: contours shorter than this were not taken for branches
  double gapArea = 0.0;       // mm^2, all saddles
  bool depthLimited = false;  // a piece still branches but maxDepth was reached
};

// Splits a part into mono-branch sub-parts (thesis 000_dbb97c2716e10cc3.txt §3.4.3). The geodesic distance
// from the base is scanned upwards for the first level where its count of contours (closed, at least
// minPerimeter long) grows; the change is bisected down to the saddle value. The mesh is then cut
// along two iso-lines of that distance (new vertices on the cut edges, shared by the faces on both
// sides, so each piece is a manifold whose boundary runs along the cut); pieces that branch again
// are split the same way from their own lower edge.
//
// Junction rule. A cut at the saddle itself would pinch (a figure-of-eight through the saddle
// vertex). So the trunk ends at saddle - g/2, where its upper edge is one clean loop, and each
// branch (a connected component of what lies above) starts at saddle + g/2, where it has a loop of
// its own. The band of height g in between, around the crotch, is the junction gap: each branch
// records it (supportGap) and lays its first ring measured from the trunk's top, across the gap,
// so the gap is built, not left (g is below h_min, so that ring still lies on the branch). Both cuts follow
// the distance smoothed at the scale of a few edges: the heat method's distance wobbles from face to face on
// meshes with slivers and a level line of it zig-zags, which a spiral started on it would repeat; the saddle
// is still bisected on the raw distance, and reported as such.
//
// `baseField`: the geodesic distance from `base` if already computed (one value per vertex).
// Throws InputError when branches join again above a split (the part has a hole through it, not a
// tree of branches) and AlgorithmError when a piece is not one clean manifold; honours
// cancellation.
BranchDecomposition splitIntoMonoBranches(const TriangleMesh& mesh, const std::vector<int>& base,
                                          const std::vector<double>* baseField,
                                          const BranchSplitOptions& options, Progress& progress);

}  // namespace spira
