// Everything of the scan area that uses PCL, in one translation unit (its templates are heavy):
// filtering, normal estimation, ICP registration and nearest-point queries.
#include <algorithm>
#include <cmath>
#include <string>

#include <pcl/console/print.h>
#include <pcl/features/normal_3d.h>
#include <pcl/filters/statistical_outlier_removal.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/registration/icp.h>
#include <pcl/search/kdtree.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/scan/scan_alignment.h"
#include "spira/scan/scan_deviation.h"
#include "spira/scan/scan_processing.h"

namespace spira {
namespace {

using Cloud = pcl::PointCloud<pcl::PointNormal>;

Cloud::Ptr toPcl(const PointCloud& cloud)
{
  Cloud::Ptr out(new Cloud);
  out->resize(cloud.size());
  const bool normals = cloud.hasNormals();
  for (size_t i = 0; i < cloud.size(); ++i) {
    pcl::PointNormal& p = (*out)[i];
    p.x = float(cloud.points[i].x()), p.y = float(cloud.points[i].y()), p.z = float(cloud.points[i].z());
    const Vec3 n = normals ? cloud.normals[i] : Vec3::Zero();
    p.normal_x = float(n.x()), p.normal_y = float(n.y()), p.normal_z = float(n.z());
  }
  return out;
}

PointCloud fromPcl(const Cloud& cloud, bool normals)
{
  PointCloud out;
  out.points.reserve(cloud.size());
  for (const pcl::PointNormal& p : cloud) out.points.emplace_back(p.x, p.y, p.z);
  if (normals)
    for (const pcl::PointNormal& p : cloud) {
      const Vec3 n(p.normal_x, p.normal_y, p.normal_z);
      out.normals.push_back(n.norm() > 1e-9 ? Vec3(n.normalized()) : Vec3::UnitZ());
    }
  return out;
}

// PCL's voxel grid indexes cells with 32-bit integers: a leaf too small for the cloud's extent would
// overflow them (PCL then keeps every point and warns). The leaf is raised to what fits.
double fittingLeaf(const PointCloud& cloud, double leaf)
{
  const Vec3 size = boundsOf(cloud).size();
  const double cells = (size.x() / leaf + 1) * (size.y() / leaf + 1) * (size.z() / leaf + 1);
  const double limit = double(std::numeric_limits<std::int32_t>::max()) / 2.0;
  return cells > limit ? leaf * std::cbrt(cells / limit) : leaf;
}

// Point-to-plane ICP that says how many iterations its last run took.
class Icp : public pcl::IterativeClosestPointWithNormals<pcl::PointNormal, pcl::PointNormal, double> {
 public:
  int iterations() const { return nr_iterations_; }
};

Cloud::Ptr voxelGrid(const Cloud::Ptr& cloud, double leaf)
{
  pcl::VoxelGrid<pcl::PointNormal> grid;
  grid.setInputCloud(cloud);
  grid.setLeafSize(float(leaf), float(leaf), float(leaf));
  Cloud::Ptr out(new Cloud);
  grid.filter(*out);
  return out;
}

}  // namespace

PointCloud filterScan(const PointCloud& cloud, const ScanFilterSettings& s, ScanFilterReport* report)
{
  if (!(s.voxelMm >= 0.0) || !std::isfinite(s.voxelMm))
    throw InputError("voxel size " + significantText(s.voxelMm, 6) + " mm",
                     "give a cell size in mm, 0 for none");
  if (s.outlierNeighbours < 2 || !(s.outlierStddev >= 0.0))
    throw InputError("outlier removal over " + std::to_string(s.outlierNeighbours) + " neighbours at " +
                         significantText(s.outlierStddev, 6) + " standard deviations",
                     "give 2 or more neighbours and 0 (off) or more standard deviations");
  ScanFilterReport r;
  r.read = cloud.size();
  Cloud::Ptr c = toPcl(cloud);
  if (s.voxelMm > 0.0 && !cloud.empty()) c = voxelGrid(c, fittingLeaf(cloud, s.voxelMm));
  r.afterVoxel = c->size();
  if (s.outlierStddev > 0.0 && c->size() > size_t(s.outlierNeighbours)) {
    pcl::StatisticalOutlierRemoval<pcl::PointNormal> sor;
    sor.setInputCloud(c);
    sor.setMeanK(s.outlierNeighbours);
    sor.setStddevMulThresh(s.outlierStddev);
    Cloud::Ptr kept(new Cloud);
    sor.filter(*kept);
    c = kept;
  }
  r.kept = c->size();
  r.outliers = r.afterVoxel - r.kept;
  if (report) *report = r;
  return fromPcl(*c, cloud.hasNormals());
}

void estimateNormals(PointCloud& cloud, int neighbours, const Vec3& inside)
{
  if (neighbours < 3)
    throw InputError("normals from " + std::to_string(neighbours) + " neighbours", "use 3 or more");
  if (cloud.size() < size_t(neighbours))
    throw InputError("a scan of " + std::to_string(cloud.size()) +
                         " points is too small to estimate normals from " + std::to_string(neighbours) +
                         " neighbours",
                     "give a denser scan, or one with normals");
  pcl::PointCloud<pcl::PointXYZ>::Ptr points(new pcl::PointCloud<pcl::PointXYZ>);
  points->resize(cloud.size());
  for (size_t i = 0; i < cloud.size(); ++i)
    (*points)[i] =
        pcl::PointXYZ(float(cloud.points[i].x()), float(cloud.points[i].y()), float(cloud.points[i].z()));
  pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> estimation;
  estimation.setInputCloud(points);
  estimation.setSearchMethod(pcl::search::KdTree<pcl::PointXYZ>::Ptr(new pcl::search::KdTree<pcl::PointXYZ>));
  estimation.setKSearch(neighbours);
  pcl::PointCloud<pcl::Normal> normals;
  estimation.compute(normals);
  cloud.normals.resize(cloud.size());
  for (size_t i = 0; i < cloud.size(); ++i) {
    Vec3 n(normals[i].normal_x, normals[i].normal_y, normals[i].normal_z);
    if (!n.allFinite() || n.norm() < 1e-9) n = (cloud.points[i] - inside).normalized();
    if (n.dot(cloud.points[i] - inside) < 0.0) n = -n;
    cloud.normals[i] = n.normalized();
  }
}

std::vector<size_t> nearestPoints(const std::vector<Vec3>& points, const std::vector<Vec3>& queries)
{
  if (points.empty()) return {};
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  cloud->resize(points.size());
  for (size_t i = 0; i < points.size(); ++i)
    (*cloud)[i] = pcl::PointXYZ(float(points[i].x()), float(points[i].y()), float(points[i].z()));
  pcl::search::KdTree<pcl::PointXYZ> tree;
  tree.setInputCloud(cloud);
  std::vector<size_t> out(queries.size(), 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, queries.size()),
                    [&](const tbb::blocked_range<size_t>& range) {
                      std::vector<int> index(1);
                      std::vector<float> squared(1);
                      for (size_t q = range.begin(); q != range.end(); ++q) {
                        const Vec3& v = queries[q];
                        if (tree.nearestKSearch(pcl::PointXYZ(float(v.x()), float(v.y()), float(v.z())), 1,
                                                index, squared) > 0)
                          out[q] = size_t(index[0]);
                      }
                    });
  return out;
}

AlignResult alignScan(const PointCloud& scan, const TriangleMesh& part, const Transform& T_initial,
                      const AlignSettings& s, Progress& progress)
{
  if (!(s.voxelMm > 0.0) || !(s.finalDistanceMm > 0.0) || s.startDistanceMm < s.finalDistanceMm ||
      s.iterationsPerStage < 1)
    throw InputError("alignment settings out of range (voxel " + significantText(s.voxelMm, 6) +
                         " mm, distances " + significantText(s.startDistanceMm, 6) + " to " +
                         significantText(s.finalDistanceMm, 6) + " mm)",
                     "give a positive voxel, a start distance at least the final one, and iterations");
  const PointCloud moved = transformed(scan, T_initial);
  Cloud::Ptr source = voxelGrid(toPcl(moved), fittingLeaf(moved, s.voxelMm));
  if (source->size() < s.minimumPoints)
    throw InputError("the scan has " + std::to_string(source->size()) +
                         " point(s) after thinning to one per " + significantText(s.voxelMm, 6) +
                         " mm cell; aligning needs " + std::to_string(s.minimumPoints),
                     "give a denser scan, or a smaller alignment cell (--voxel)");
  // The fit is the least-squares mean of many residuals: a few tens of thousands of points pin it to
  // well under the scan's noise, and more only cost time. Every k-th keeps them spread over the scan.
  if (source->size() > s.fitPoints) {
    const size_t stride = (source->size() + s.fitPoints - 1) / s.fitPoints;
    Cloud::Ptr thinned(new Cloud);
    for (size_t i = 0; i < source->size(); i += stride) thinned->push_back((*source)[i]);
    source = thinned;
  }
  // The target's tangent planes are its facets' own, so a sample per voxel finds the right facet.
  Cloud::Ptr target = toPcl(sampleSurface(part, s.voxelMm));
  progress.checkCancel();

  AlignResult out;
  out.pointsUsed = source->size();
  Eigen::Matrix4d total = Eigen::Matrix4d::Identity();
  // PCL prints why a fit stops ("not enough correspondences") on stderr; the overlap check below says
  // it to the user with what to do; PCL's own console lines would only repeat it half-explained.
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  Icp icp;
  icp.setInputTarget(target);
  // A step of 1e-5 mm (squared: 1e-10) or less ends a stage: far below any scanner's resolution.
  icp.setTransformationEpsilon(1e-10);
  icp.setMaximumIterations(s.iterationsPerStage);
  // Three stages, the rejection distance shrinking geometrically to the final one.
  const int stages = 3;
  Cloud::Ptr current = source;
  for (int stage = 0; stage < stages; ++stage) {
    const double t = double(stage) / double(stages - 1);
    const double distance = s.startDistanceMm * std::pow(s.finalDistanceMm / s.startDistanceMm, t);
    icp.setMaxCorrespondenceDistance(distance);
    icp.setInputSource(current);
    Cloud::Ptr aligned(new Cloud);
    icp.align(*aligned);
    out.iterations += icp.iterations();
    out.converged = icp.hasConverged();
    total = icp.getFinalTransformation() * total;
    current = aligned;
    progress.report(double(stage + 1) / double(stages), "aligning the scan");
    progress.checkCancel();
  }
  // Residual and overlap against the part's surface itself.
  const MeshDistance surface(part);
  double sum = 0.0;
  size_t inliers = 0;
  for (const pcl::PointNormal& p : *current) {
    const double d = surface.closest(Vec3(p.x, p.y, p.z)).signedDistance;
    if (std::abs(d) > s.finalDistanceMm) continue;
    sum += d * d;
    ++inliers;
  }
  out.inlierFraction = double(inliers) / double(current->size());
  out.rmsMm = inliers > 0 ? std::sqrt(sum / double(inliers)) : 0.0;
  Transform fit = Transform::Identity();
  fit.matrix() = total;
  out.T_part_scan = fit * T_initial;
  if (out.inlierFraction < 0.5)
    throw InputError("the scan does not overlap the part: after aligning, " +
                         significantText(100.0 * out.inlierFraction, 3) + " % of its points lie within " +
                         significantText(s.finalDistanceMm, 6) + " mm of the part's surface",
                     "check that the scan is of this part and in mm, or bring it closer first (an initial "
                     "transform, or three picked point pairs)");
  return out;
}

}  // namespace spira
