#include "envelope_projection.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>

#include <tbb/parallel_for.h>

#include "loop_crossing.h"
#include "ray_caster.h"
#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/base/units.h"
#include "spira/mesh/corner_normals.h"

namespace spira {

namespace {

struct Sample {
  double z = 0.0;
  Vec3 position = Vec3::Zero();
  Vec3 normal = Vec3::UnitX();
};

struct Failure {
  double z = 0.0;
  std::string what;
};

// Casts the envelope rays: from the envelope point at height z and angle theta towards the axis
// point at the same height.
class Projector {
 public:
  Projector(const TriangleMesh& mesh, const ProjectionAxis& axis, double radius)
      : mesh_(mesh),
        caster_(mesh),
        normals_(mesh.vertexNormals()),
        corners_(cornerNormals(mesh)),
        axis_(axis),
        radius_(radius)
  {
  }
  const std::vector<Vec3>& vertexNormals() const { return normals_; }

  std::optional<Sample> cast(double z, const Vec3& along) const
  {
    const Vec3 origin = axis_.pointAt(z) + radius_ * along;
    const std::optional<SurfacePoint> hit = caster_.nearest(origin, -along, radius_);
    if (!hit) return std::nullopt;
    Sample s;
    s.z = z;
    s.position = hit->position;
    s.position.z() = z;  // exact: the ray is horizontal
    s.normal = surfaceNormalAt(mesh_, corners_, *hit);
    return s;
  }

 private:
  const TriangleMesh& mesh_;
  RayCaster caster_;
  std::vector<Vec3> normals_;
  std::vector<Vec3> corners_;
  const ProjectionAxis& axis_;
  double radius_;
};

struct Tracer {
  const Projector& projector;
  Vec3 along;
  double jump;   // largest step between consecutive samples before it is bisected, mm
  double minDz;  // bisection stops here: a step still open is a jump in the surface
  size_t rays = 0;
  std::optional<Failure> failure;

  std::optional<Sample> cast(double z)
  {
    ++rays;
    std::optional<Sample> s = projector.cast(z, along);
    if (!s && !failure)
      failure = Failure{z,
                        "the projection ray meets no surface there (the wall has a gap or the part "
                        "leaves the envelope's reach)"};
    return s;
  }

  // Appends samples strictly between a and b until consecutive ones are at most `jump` apart.
  bool bridge(const Sample& a, const Sample& b, std::vector<Sample>& out)
  {
    const double gap = (b.position - a.position).norm();
    if (gap <= jump) return true;
    const double zm = 0.5 * (a.z + b.z);
    if (b.z - a.z < minDz) {
      failure = Failure{zm, "the projected points jump " + fixedText(gap, 2) +
                                " mm across the wall, which folds back (an overhang): the surface "
                                "it hides gets no projection"};
      return false;
    }
    const std::optional<Sample> m = cast(zm);
    if (!m) return false;
    if (!bridge(a, *m, out)) return false;
    out.push_back(*m);
    return bridge(*m, b, out);
  }
};

// The envelope generatrix at one angle, projected at heights dz apart (finer where needed).
struct FineLine {
  std::vector<Sample> samples;  // base crossing first, top crossing last
  double length = 0.0;
  size_t rays = 0;
  std::optional<Failure> failure;
};

Sample edgeSample(const EdgePoint& e)
{
  return Sample{e.position.z(), e.position, e.normal};
}

FineLine traceLine(const Projector& projector, const EdgePoint& base, const EdgePoint& top, const Vec3& along,
                   double dz)
{
  FineLine out;
  const double z0 = base.position.z(), z1 = top.position.z();
  Tracer tracer{projector, along, 3.0 * dz, 1e-7 * std::max(1.0, z1 - z0), 0, std::nullopt};
  const size_t steps = static_cast<size_t>(std::max(1.0, std::ceil((z1 - z0) / dz)));
  Sample previous = edgeSample(base);
  out.samples.push_back(previous);
  for (size_t k = 1; k <= steps && !tracer.failure; ++k) {
    std::optional<Sample> next =
        k == steps ? std::optional<Sample>(edgeSample(top)) : tracer.cast(z0 + (z1 - z0) * k / steps);
    if (!next || !tracer.bridge(previous, *next, out.samples)) break;
    out.samples.push_back(*next);
    previous = *next;
  }
  out.rays = tracer.rays;
  out.failure = tracer.failure;
  for (size_t i = 1; i < out.samples.size(); ++i)
    out.length += (out.samples[i].position - out.samples[i - 1].position).norm();
  return out;
}

// `segments` + 1 points evenly spread along the line's arc length. Interior points are cast again
// at the height their arc length falls at, so that they lie on the surface, not on a chord.
void resampleLine(const Projector& projector, const FineLine& line, const Vec3& along, size_t segments,
                  Polyline& points, std::vector<Vec3>& normals, size_t& rays)
{
  const auto& s = line.samples;
  points.assign(segments + 1, Vec3::Zero());
  normals.assign(segments + 1, Vec3::UnitX());
  points.front() = s.front().position;
  normals.front() = s.front().normal;
  points.back() = s.back().position;
  normals.back() = s.back().normal;
  size_t k = 1;
  double walked = 0.0;  // arc length at s[k - 1]
  for (size_t j = 1; j < segments; ++j) {
    const double target = line.length * static_cast<double>(j) / static_cast<double>(segments);
    double step = (s[k].position - s[k - 1].position).norm();
    while (walked + step < target && k + 1 < s.size()) {
      walked += step;
      ++k;
      step = (s[k].position - s[k - 1].position).norm();
    }
    const double t = step > 0 ? std::clamp((target - walked) / step, 0.0, 1.0) : 0.0;
    const Vec3 chord = s[k - 1].position + t * (s[k].position - s[k - 1].position);
    ++rays;
    const std::optional<Sample> exact = projector.cast(chord.z(), along);
    // The re-cast point is kept when it lands on the same stretch of wall (it always should: the
    // fine samples are continuous), else the chord point stands in.
    if (exact && (exact->position - chord).norm() <= step + 1e-9) {
      points[j] = exact->position;
      normals[j] = exact->normal;
    } else {
      points[j] = chord;
      normals[j] = ((1 - t) * s[k - 1].normal + t * s[k].normal).normalized();
    }
  }
}

double envelopeRadius(const TriangleMesh& mesh, const ProjectionAxis& axis)
{
  double reach = 0.0;
  for (const Vec3& v : mesh.vertices)
    reach = std::max(reach, (Eigen::Vector2d(v.x(), v.y()) - axis.at(v.z())).norm());
  return 1.05 * reach + 2.0 * mesh.meanEdgeLength();
}

void requireAroundAxis(const TriangleMesh& mesh, const BoundaryLoop& loop, const ProjectionAxis& axis,
                       const char* which)
{
  const int turns = loopWinding(mesh, loop, axis);
  if (std::abs(turns) != 1)
    throw InputError(std::string("the ") + which + " free edge goes " + std::to_string(std::abs(turns)) +
                         " times around the projection axis instead of once",
                     "envelope projection needs the axis inside the part; use the iso-value strategy "
                     "(--strategy isovalue) for this part");
}

}  // namespace

EnvelopeDecomposition decomposeByEnvelopeProjection(const TriangleMesh& mesh, const BoundaryLoop& lower,
                                                    const BoundaryLoop& upper, const ProjectionAxis& axis,
                                                    const EnvelopeOptions& options, Progress& progress)
{
  const size_t n = options.generatrixCount;
  if (n < 3)
    throw InputError("the generatrix count must be at least 3, not " + std::to_string(n), "raise it");
  if (lower.vertices.size() < 3 || upper.vertices.size() < 3)
    throw InputError("envelope projection needs a lower and an upper free edge of 3 or more vertices",
                     "check that the part is open at the top and the bottom");
  requireAroundAxis(mesh, lower, axis, "lower");
  requireAroundAxis(mesh, upper, axis, "upper");

  EnvelopeDecomposition out;
  const double meanEdge = mesh.meanEdgeLength();
  out.pointSpacing = options.pointSpacing > 0 ? options.pointSpacing : meanEdge;
  // Sample at half the finer of the spacing and the mesh resolution: a fold narrower than that
  // could slip between two samples unnoticed.
  const double dz = 0.5 * std::min(out.pointSpacing, meanEdge);
  out.envelopeRadius = envelopeRadius(mesh, axis);
  const Projector projector(mesh, axis, out.envelopeRadius);

  std::vector<FineLine> lines(n);
  std::vector<std::optional<Failure>> edgeFailures(n);
  std::vector<Vec3> alongs(n);
  const size_t block = 16;
  for (size_t first = 0; first < n; first += block) {
    progress.checkCancel();
    progress.report(0.8 * static_cast<double>(first) / static_cast<double>(n), "envelope projection");
    tbb::parallel_for(first, std::min(n, first + block), [&](size_t m) {
      const double theta = options.startAngle + 2.0 * kPi * static_cast<double>(m) / static_cast<double>(n);
      alongs[m] = Vec3(std::cos(theta), std::sin(theta), 0.0);
      const auto base = loopCrossing(mesh, projector.vertexNormals(), lower, axis, theta);
      const auto top = loopCrossing(mesh, projector.vertexNormals(), upper, axis, theta);
      if (!base || !top || top->position.z() <= base->position.z()) {
        const double z = base ? base->position.z() : top ? top->position.z() : axis.points().front().z();
        edgeFailures[m] = Failure{z, !base || !top ? "a free edge does not cross this angle"
                                                   : "the upper edge is not above the lower one"};
        return;
      }
      lines[m] = traceLine(projector, *base, *top, alongs[m], dz);
    });
  }

  // Report the lowest failure: where the trouble starts.
  size_t failing = 0;
  std::optional<std::pair<Failure, size_t>> first;
  for (size_t m = 0; m < n; ++m) {
    const std::optional<Failure>& f = edgeFailures[m] ? edgeFailures[m] : lines[m].failure;
    if (!f) continue;
    ++failing;
    if (!first || f->z < first->first.z) first = std::make_pair(*f, m);
  }
  if (first) {
    const double angle = radToDeg(
        std::remainder(options.startAngle + 2.0 * kPi * first->second / static_cast<double>(n), 2 * kPi));
    throw InputError("envelope projection fails at z = " + fixedText(first->first.z, 2) + " mm, angle " +
                         fixedText(angle, 1) + " deg: " + first->first.what + " (" + std::to_string(failing) +
                         " of " + std::to_string(n) + " generatrices fail)",
                     "envelope projection suits open parts without overhangs; use the iso-value strategy "
                     "(--strategy isovalue) or the geodesic one (--strategy geodesic)");
  }

  double total = 0.0;
  for (const FineLine& l : lines) {
    total += l.length;
    out.raysCast += l.rays;
  }
  const double mean = total / static_cast<double>(n);
  const size_t segments = static_cast<size_t>(std::max(1.0, std::ceil(mean / out.pointSpacing - 1e-9)));
  progress.report(0.8, "resampling generatrices");
  Generatrices& g = out.generatrices;
  g.lines.resize(n);
  g.normals.resize(n);
  std::vector<size_t> rays(n, 0);
  tbb::parallel_for(size_t(0), n, [&](size_t m) {
    resampleLine(projector, lines[m], alongs[m], segments, g.lines[m], g.normals[m], rays[m]);
  });
  progress.checkCancel();
  for (size_t r : rays) out.raysCast += r;
  progress.report(1.0, "envelope projection");
  return out;
}

}  // namespace spira
