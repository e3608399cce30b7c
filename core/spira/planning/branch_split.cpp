#include "spira/planning/branch_split.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/contour/branch_levels.h"
#include "spira/contour/mesh_split.h"
#include "spira/field/heat_distance.h"
#include "spira/planning/field_smoothing.h"

namespace spira {

namespace {

double meanOn(const std::vector<int>& vertices, const std::vector<double>& field)
{
  double sum = 0.0;
  for (int v : vertices) sum += field[static_cast<size_t>(v)];
  return vertices.empty() ? std::numeric_limits<double>::infinity()
                          : sum / static_cast<double>(vertices.size());
}

// A piece of the working mesh as a part of its own, checked to be plannable, with its lower edge:
// the boundary loop lowest in the splitting field.
BranchPiece makePiece(const TriangleMesh& mesh, const std::vector<double>& field,
                      const std::vector<int>& faces, bool trunk)
{
  SubMesh sub = extractFaces(mesh, faces);
  BranchPiece p;
  p.trunk = trunk;
  p.mesh = std::move(sub.mesh);
  p.field.resize(sub.parentVertex.size());
  for (size_t v = 0; v < sub.parentVertex.size(); ++v)
    p.field[v] = field[static_cast<size_t>(sub.parentVertex[v])];
  p.report = validateMesh(p.mesh);
  p.area = p.report.area;
  if (!p.report.isPlannable() || p.report.componentCount != 1 || p.report.boundaryLoops.empty())
    throw AlgorithmError("splitting the part into branches left a piece that is not one clean wall (" +
                             std::to_string(p.report.componentCount) + " component(s), " +
                             std::to_string(p.report.boundaryLoops.size()) + " free edge(s))",
                         "remesh the part more finely around the junction of its branches");
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < p.report.boundaryLoops.size(); ++i) {
    const double m = meanOn(p.report.boundaryLoops[i].vertices, p.field);
    if (m < best) {
      best = m;
      p.lowerLoop = static_cast<int>(i);
    }
  }
  p.lowerLevel = std::numeric_limits<double>::infinity();
  for (int v : p.report.boundaryLoops[static_cast<size_t>(p.lowerLoop)].vertices)
    p.lowerLevel = std::min(p.lowerLevel, p.field[static_cast<size_t>(v)]);
  return p;
}

struct SaddleCut {
  BranchPiece trunk;
  std::vector<BranchPiece> branches;
  double gapArea = 0.0;
};

// Cuts `piece` along cutField = trunkTop and cutField = branchBase: the trunk below the first, the
// `branchCount` largest connected components above the second as branches (ordered by x then y
// of their centroids), the band between (and any small bump above it) left out.
SaddleCut cutAtSaddle(const BranchPiece& piece, const std::vector<double>& cutField, double trunkTop,
                      double branchBase, size_t branchCount)
{
  const LevelCut first = cutAlongLevel(piece.mesh, cutField, trunkTop);
  const std::vector<double> raw1 = carryToCut(first, piece.field);
  const std::vector<double> cut1 = carryToCut(first, cutField);
  const LevelCut second = cutAlongLevel(first.mesh, cut1, branchBase, &first.above);
  const std::vector<double> raw = carryToCut(second, raw1);
  const TriangleMesh& mesh = second.mesh;

  std::vector<int> trunkFaces;
  std::vector<std::uint8_t> above(mesh.faceCount(), 0);
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const bool overTrunk = first.above[static_cast<size_t>(second.parentFace[f])] != 0;
    if (!overTrunk) trunkFaces.push_back(static_cast<int>(f));
    above[f] = overTrunk && second.above[f];
  }
  std::vector<int> component;
  const int count = faceComponents(mesh, above, component);
  if (static_cast<size_t>(count) < branchCount)
    throw InputError("the branches that part at " + significantText(0.5 * (trunkTop + branchBase), 4) +
                         " mm from the base join again further up: the part has a hole through it, "
                         "not a tree of branches",
                     "split the part into pieces without loops in the CAD tool and plan each one");
  std::vector<double> area(static_cast<size_t>(count), 0.0);
  std::vector<Vec3> centroid(static_cast<size_t>(count), Vec3::Zero());
  std::vector<std::vector<int>> faces(static_cast<size_t>(count));
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    if (component[f] < 0) continue;
    const auto c = static_cast<size_t>(component[f]);
    const double a = mesh.faceArea(f);
    const Face& fc = mesh.faces[f];
    area[c] += a;
    centroid[c] += a * (mesh.vertices[fc[0]] + mesh.vertices[fc[1]] + mesh.vertices[fc[2]]) / 3.0;
    faces[c].push_back(static_cast<int>(f));
  }
  std::vector<int> order(static_cast<size_t>(count));
  for (int c = 0; c < count; ++c) order[static_cast<size_t>(c)] = c;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return area[a] > area[b]; });
  order.resize(branchCount);
  for (int c : order) centroid[static_cast<size_t>(c)] /= area[static_cast<size_t>(c)];
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const Vec3 &p = centroid[static_cast<size_t>(a)], &q = centroid[static_cast<size_t>(b)];
    return p.x() != q.x() ? p.x() < q.x() : p.y() < q.y();
  });

  SaddleCut out;
  out.trunk = makePiece(mesh, raw, trunkFaces, true);
  double kept = out.trunk.area;
  for (int c : order) {
    out.branches.push_back(makePiece(mesh, raw, faces[static_cast<size_t>(c)], false));
    kept += out.branches.back().area;
  }
  out.gapArea = std::max(0.0, mesh.area() - kept);
  return out;
}

class Splitter {
 public:
  Splitter(const BranchSplitOptions& options, BranchDecomposition& out, Progress& progress)
      : options_(options), out_(out), progress_(progress)
  {
  }

  void split(BranchPiece piece, int parent, int depth)
  {
    progress_.checkCancel();
    piece.parent = parent;
    piece.depth = depth;
    BranchScanOptions scan;
    scan.minPerimeter = options_.minPerimeter;
    const std::vector<int>& lower = piece.report.boundaryLoops[static_cast<size_t>(piece.lowerLoop)].vertices;
    const BranchSplit s =
        findFirstBranchSplit(piece.mesh, piece.field, highestValueOn(lower, piece.field), scan, progress_);
    if (!s.found || depth >= options_.maxDepth) {
      out_.depthLimited = out_.depthLimited || s.found;
      out_.pieces.push_back(std::move(piece));
      return;
    }
    // The cuts follow the smoothed distance, around its own saddle.
    std::vector<double> cutField = piece.field;
    double saddle = s.saddle;
    if (options_.smoothing > 0) {
      std::vector<double> smooth = smoothField(piece.mesh, piece.field, options_.smoothing);
      const BranchSplit ss =
          findFirstBranchSplit(piece.mesh, smooth, highestValueOn(lower, smooth), scan, progress_);
      if (ss.found) {
        cutField = std::move(smooth);
        saddle = ss.saddle;
      }
    }
    const double minPerimeter =
        options_.minPerimeter > 0 ? options_.minPerimeter : 3.0 * piece.mesh.meanEdgeLength();
    double half = std::min(0.5 * out_.junctionGap, 0.5 * (saddle - highestValueOn(lower, cutField)));
    size_t branches = 0;
    for (int tries = 0; tries < 8; ++tries, half *= 0.5) {
      branches =
          significantContourCount(extractIsoContour(piece.mesh, cutField, saddle + half), minPerimeter);
      if (branches >= 2) break;
    }
    if (branches < 2)
      throw AlgorithmError("the part branches at " + significantText(s.saddle, 4) + " mm from the base" +
                               " but its branches could not be told apart above it",
                           "remesh the part more finely around the junction of its branches");
    SaddleCut cut = cutAtSaddle(piece, cutField, saddle - half, saddle + half, branches);
    cut.trunk.parent = parent;
    cut.trunk.depth = depth;
    const int trunkIndex = static_cast<int>(out_.pieces.size());
    out_.pieces.push_back(std::move(cut.trunk));
    BranchSaddle record;
    record.piece = trunkIndex;
    record.level = s.saddle;
    record.bisections = s.bisections;
    record.position = s.position;
    record.branches = branches;
    record.trunkTop = saddle - half;
    record.branchBase = saddle + half;
    record.gapArea = cut.gapArea;
    out_.saddles.push_back(record);
    out_.gapArea += cut.gapArea;
    for (BranchPiece& b : cut.branches) {
      b.supportGap = 2.0 * half;
      // Each branch is scanned with the distance from its own lower edge, as if it stood alone.
      const std::vector<int> bottom = b.report.boundaryLoops[static_cast<size_t>(b.lowerLoop)].vertices;
      b.field = heatGeodesicDistance(b.mesh, bottom);
      split(std::move(b), trunkIndex, depth + 1);
    }
  }

 private:
  const BranchSplitOptions& options_;
  BranchDecomposition& out_;
  Progress& progress_;
};

}  // namespace

BranchDecomposition splitIntoMonoBranches(const TriangleMesh& mesh, const std::vector<int>& base,
                                          const std::vector<double>* baseField,
                                          const BranchSplitOptions& options, Progress& progress)
{
  if (base.empty()) throw InputError("the part has no lower edge", "check the part's free edges");
  if (baseField && baseField->size() != mesh.vertexCount())
    throw InputError("the base field has " + std::to_string(baseField->size()) + " values for " +
                         std::to_string(mesh.vertexCount()) + " vertices",
                     "compute the geodesic distance from the base on this mesh");
  BranchDecomposition out;
  out.field = baseField ? *baseField : heatGeodesicDistance(mesh, base, HeatDistanceOptions{}, progress);
  out.junctionGap = options.junctionGap > 0 ? options.junctionGap : 0.5 * options.thinnestDeposit;
  out.minPerimeter = options.minPerimeter;

  std::vector<int> all(mesh.faceCount());
  for (size_t f = 0; f < all.size(); ++f) all[f] = static_cast<int>(f);
  BranchPiece root = makePiece(mesh, out.field, all, true);
  Splitter(options, out, progress).split(std::move(root), -1, 0);
  return out;
}

}  // namespace spira
