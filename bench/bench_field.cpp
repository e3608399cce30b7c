// Scalar-field benchmark: Spira's heat-method distance against CGAL's Heat_method_3 and against
// the floor of any factorising method (one CHOLMOD supernodal factorisation), on domes of about
// 100k and 1M triangles (and a jittered 100k one) with the whole base loop as the source set.
// Prints a table.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <cholmod.h>

#include "spira/field/cotan_laplacian.h"
#include "spira/field/field_ops.h"
#include "spira/field/harmonic_field.h"
#include "spira/field/heat_distance.h"
#include "spira/field/mesh_adjacency.h"

namespace {

using spira::Face;
using spira::TriangleMesh;
using spira::Vec3;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t)
{
  return std::chrono::duration<double>(Clock::now() - t).count();
}

double cpuSeconds()
{
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

std::string loadAverage()
{
  std::ifstream in("/proc/loadavg");
  std::string one;
  in >> one;
  return one.empty() ? "?" : one;
}

double maxRssMiB()
{
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

// Peak resident memory since the last reset (Linux VmHWM); -1 where not available.
void resetPeakRss()
{
  std::ofstream("/proc/self/clear_refs") << "5";
}
double peakRssMiB()
{
  std::ifstream in("/proc/self/status");
  std::string key;
  while (in >> key) {
    if (key == "VmHWM:") {
      double kb = 0;
      in >> kb;
      return kb / 1024.0;
    }
    std::getline(in, key);
  }
  return -1.0;
}

// Dome of radius r with nearly equilateral triangles: latitude rings whose vertex count follows
// the radius, joined by walking both rings in angle order. Base ring first (the sources).
struct Dome {
  TriangleMesh mesh;
  std::vector<int> base;
};

Dome makeDome(double r, double edge)
{
  Dome d;
  const int n = std::max(2, int(std::lround(0.5 * M_PI * r / (edge * std::sqrt(3.0) / 2.0))));
  std::vector<int> start, count;
  for (int i = 0; i < n; ++i) {
    const double polar = 0.5 * M_PI * (1.0 - double(i) / n), rr = r * std::sin(polar);
    const int m = std::max(6, int(std::lround(2.0 * M_PI * rr / edge)));
    start.push_back(int(d.mesh.vertices.size()));
    count.push_back(m);
    for (int k = 0; k < m; ++k) {
      const double a = 2.0 * M_PI * (k + 0.5 * (i % 2)) / m;
      d.mesh.vertices.emplace_back(rr * std::cos(a), rr * std::sin(a), r * std::cos(polar));
    }
  }
  for (int i = 0; i + 1 < n; ++i) {
    const int a = start[i], na = count[i], b = start[i + 1], nb = count[i + 1];
    const double offA = 0.5 * (i % 2), offB = 0.5 * ((i + 1) % 2);
    for (int ia = 0, ib = 0; ia < na || ib < nb;) {
      const bool advanceA = ib >= nb || (ia < na && (ia + 1 + offA) / na < (ib + 1 + offB) / nb);
      if (advanceA) {
        d.mesh.faces.push_back({a + ia % na, a + (ia + 1) % na, b + ib % nb});
        ++ia;
      } else {
        d.mesh.faces.push_back({a + ia % na, b + (ib + 1) % nb, b + ib % nb});
        ++ib;
      }
    }
  }
  const int pole = int(d.mesh.vertices.size());
  d.mesh.vertices.emplace_back(0.0, 0.0, r);
  for (int k = 0; k < count.back(); ++k)
    d.mesh.faces.push_back({start.back() + k, start.back() + (k + 1) % count.back(), pole});
  for (int k = 0; k < count.front(); ++k) d.base.push_back(k);
  return d;
}

// Every vertex but the base loop and the pole moved by up to `jitter` edges in each coordinate
// and put back on the sphere (fixed seed): irregular triangles on the same exact surface.
void jitterDome(Dome& d, double r, double edge, double jitter)
{
  std::mt19937 rng(11u);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const size_t pole = d.mesh.vertices.size() - 1;
  for (size_t v = d.base.size(); v < pole; ++v) {
    Vec3& p = d.mesh.vertices[v];
    p += jitter * edge * Vec3(unit(rng), unit(rng), unit(rng));
    p.z() = std::max(p.z(), 0.1 * edge);
    p = r * p.normalized();
  }
}

struct Accuracy {
  double mean = 0.0, max = 0.0, poleError = 0.0;
};

// Against R times the elevation angle, on vertices farther than 5 mean edges from the base.
Accuracy accuracy(const Dome& d, double r, double h, const std::function<double(int)>& phi)
{
  Accuracy a;
  int count = 0;
  for (size_t v = 0; v < d.mesh.vertices.size(); ++v) {
    const double exact = r * std::asin(std::clamp(d.mesh.vertices[v].z() / r, -1.0, 1.0));
    if (exact <= 5.0 * h) continue;
    const double e = std::abs(phi(int(v)) - exact) / exact;
    a.mean += e;
    a.max = std::max(a.max, e);
    ++count;
  }
  a.mean /= std::max(count, 1);
  a.poleError = std::abs(phi(int(d.mesh.vertices.size()) - 1) - 0.5 * M_PI * r);
  return a;
}

struct Row {
  std::string name;
  double seconds = 0.0;
  std::string detail;
  Accuracy acc;
  bool hasAccuracy = false;
  double peakMiB = -1.0;
};

void printRows(const std::vector<Row>& rows)
{
  std::printf("  %-44s %9s %10s %10s %9s %9s  %s\n", "method", "time [s]", "mean err", "max err", "pole [mm]",
              "peak MiB", "notes");
  for (const Row& r : rows) {
    if (r.hasAccuracy)
      std::printf("  %-44s %9.3f %9.4f%% %9.4f%% %9.4f %9.0f  %s\n", r.name.c_str(), r.seconds,
                  100 * r.acc.mean, 100 * r.acc.max, r.acc.poleError, r.peakMiB, r.detail.c_str());
    else
      std::printf("  %-44s %9.3f %10s %10s %9s %9.0f  %s\n", r.name.c_str(), r.seconds, "", "", "", r.peakMiB,
                  r.detail.c_str());
  }
}

// The best of `repeats` runs (the machine is shared); the notes give that run's stages.
Row runSpira(const Dome& d, double r, int repeats, const spira::HeatDistanceOptions& options,
             const char* name)
{
  Row row;
  row.seconds = 1e300;
  for (int k = 0; k < repeats; ++k) {
    resetPeakRss();
    const double cpu0 = cpuSeconds();
    const auto t = Clock::now();
    spira::HeatDistanceSolver solver(d.mesh, options);
    const std::vector<double> phi = solver.compute(d.base);
    const double seconds = since(t), cpu = cpuSeconds() - cpu0;
    row.peakMiB = std::max(row.peakMiB, peakRssMiB());
    if (seconds >= row.seconds) continue;
    row.seconds = seconds;
    const spira::HeatDistanceSetupStats& s = solver.setupStats();
    const double solveSeconds = solver.lastStats().seconds;
    const auto t2 = Clock::now();
    const std::vector<double> again = solver.compute(d.base);
    const double reuse = since(t2);
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "operators %.2f, order+analysis %.2f, 2 factorisations %.2f, solve %.2f (cpu %.1f); "
                  "reuse %.2f; nnz(L) %.1fM",
                  s.operatorSeconds, s.analysisSeconds, s.factorSeconds, solveSeconds, cpu, reuse,
                  s.factorNonZeros / 1e6);
    row.detail = buf;
    row.acc = accuracy(d, r, solver.meanEdgeLength(), [&](int v) { return phi[v]; });
  }
  row.name = name;
  row.hasAccuracy = true;
  return row;
}

Row runCgal(const Dome& d, double r, double h)
{
  using Kernel = CGAL::Simple_cartesian<double>;
  using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
  using VertexIndex = SurfaceMesh::Vertex_index;
  Row row;
  resetPeakRss();
  const double cpu0 = cpuSeconds();
  auto t = Clock::now();
  SurfaceMesh sm;
  sm.reserve(d.mesh.vertices.size(), 3 * d.mesh.faces.size() / 2, d.mesh.faces.size());
  for (const Vec3& p : d.mesh.vertices) sm.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z()));
  for (const Face& f : d.mesh.faces) sm.add_face(VertexIndex(f[0]), VertexIndex(f[1]), VertexIndex(f[2]));
  const double build = since(t);
  t = Clock::now();
  auto distance = sm.add_property_map<VertexIndex, double>("v:distance", 0.0).first;
  CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<SurfaceMesh> hm(sm);
  const double setup = since(t);
  for (int v : d.base) hm.add_source(VertexIndex(v));
  hm.estimate_geodesic_distances(distance);
  row.seconds = build + since(t);
  row.peakMiB = peakRssMiB();
  char buf[160];
  std::snprintf(buf, sizeof buf,
                "Surface_mesh %.2f, constructor (2 SimplicialLDLT) %.2f, solve %.2f (cpu %.1f)", build, setup,
                row.seconds - build - setup, cpuSeconds() - cpu0);
  row.name = "(b) CGAL Heat_method_3, end to end";
  row.detail = buf;
  row.acc = accuracy(d, r, h, [&](int v) { return distance[VertexIndex(v)]; });
  row.hasAccuracy = true;
  return row;
}

// One supernodal CHOLMOD analysis + factorisation of the heat operator A - t L_C.
Row runCholmod(const spira::SymmetricSparseMatrix& k, int ordering, const std::string& label,
               const std::vector<int>* order = nullptr)
{
  Row row;
  cholmod_common c;
  cholmod_start(&c);
  c.supernodal = CHOLMOD_SUPERNODAL;
  if (ordering >= 0) {
    c.nmethods = 1;
    c.method[0].ordering = ordering;
  }
  cholmod_sparse a{};
  a.nrow = a.ncol = size_t(k.size);
  a.nzmax = size_t(k.nonZeros());
  a.p = const_cast<int*>(k.columnStart.data());
  a.i = const_cast<int*>(k.rowIndex.data());
  a.x = const_cast<double*>(k.values.data());
  a.stype = -1;
  a.itype = CHOLMOD_INT;
  a.xtype = CHOLMOD_REAL;
  a.dtype = CHOLMOD_DOUBLE;
  a.sorted = a.packed = 1;
  resetPeakRss();
  auto t = Clock::now();
  cholmod_factor* l = order ? cholmod_analyze_p(&a, const_cast<int*>(order->data()), nullptr, 0, &c)
                            : cholmod_analyze(&a, &c);
  const double analyse = since(t);
  const auto t2 = Clock::now();
  cholmod_factorize(&a, l, &c);
  const double factor = since(t2);
  row.seconds = since(t);
  row.peakMiB = peakRssMiB();
  char buf[160];
  std::snprintf(buf, sizeof buf, "analyse %.2f + factorise %.2f; nnz(L) %.1fM, %.1f GFlop%s", analyse, factor,
                c.lnz / 1e6, c.fl / 1e9, c.status == CHOLMOD_OK ? "" : " (FAILED)");
  row.name = label;
  row.detail = buf;
  cholmod_free_factor(&l, &c);
  cholmod_finish(&c);
  return row;
}

void benchmark(double r, double edge, bool withCgal, int repeats, double jitter = 0.0)
{
  Dome d = makeDome(r, edge);
  char label[48] = "";
  if (jitter > 0.0) {
    jitterDome(d, r, edge, jitter);
    std::snprintf(label, sizeof label, ", jittered by %.1f edges", jitter);
  }
  std::printf(
      "\nDome R = %.0f mm%s: %zu vertices, %zu triangles, %zu source vertices (the base loop); load average "
      "%s\n",
      r, label, d.mesh.vertices.size(), d.mesh.faces.size(), d.base.size(), loadAverage().c_str());
  std::vector<Row> rows;
  rows.push_back(runSpira(d, r, repeats, {}, "(a) Spira HeatDistanceSolver, end to end"));
  std::printf("  max RSS (getrusage) of the process with the mesh and (a): %.0f MiB\n", maxRssMiB());
  spira::HeatDistanceOptions plain;
  plain.refinementSteps = 0;
  rows.push_back(runSpira(d, r, repeats, plain, "    same, plain heat method (no refinement)"));

  // The heat operator, assembled as Spira does (not timed: (c) is the factorisation alone).
  const spira::MeshAdjacency adjacency = spira::buildMeshAdjacency(d.mesh);
  const spira::CotanLaplacian op = spira::buildCotanLaplacian(d.mesh, adjacency);
  spira::SymmetricSparseMatrix heat = op.stiffness;
  const double t = op.meanEdgeLength * op.meanEdgeLength;
  for (double& x : heat.values) x *= t;
  for (int v = 0; v < heat.size; ++v) heat.values[heat.columnStart[v]] += op.vertexArea[v];
  rows.push_back(runCholmod(heat, -1, "(c) one CHOLMOD factorisation, default order"));
  rows.push_back(runCholmod(heat, CHOLMOD_AMD, "    same, AMD order"));
  rows.push_back(runCholmod(heat, CHOLMOD_METIS, "    same, METIS order"));

  if (withCgal) rows.push_back(runCgal(d, r, op.meanEdgeLength));
  printRows(rows);
  if (withCgal)
    std::printf("  speed-up of (a) over (b): %.1fx (plain: %.1fx)\n",
                rows.back().seconds / rows.front().seconds, rows.back().seconds / rows[1].seconds);
}

// Open tube of radius r and height H: staggered rings of equal count (equilateral triangles).
struct Tube {
  TriangleMesh mesh;
  std::vector<int> lower, upper;
};

Tube makeTube(double r, double height, double edge)
{
  Tube t;
  const int m = int(std::lround(2.0 * M_PI * r / edge));
  const int rings = int(std::lround(height / (edge * std::sqrt(3.0) / 2.0)));
  for (int i = 0; i <= rings; ++i)
    for (int k = 0; k < m; ++k) {
      const double a = 2.0 * M_PI * (k + 0.5 * (i % 2)) / m;
      t.mesh.vertices.emplace_back(r * std::cos(a), r * std::sin(a), height * i / rings);
    }
  for (int i = 0; i < rings; ++i)
    for (int k = 0; k < m; ++k) {
      const int a0 = i * m + k, a1 = i * m + (k + 1) % m, b0 = (i + 1) * m + k,
                b1 = (i + 1) * m + (k + 1) % m;
      if (i % 2 == 0) {
        t.mesh.faces.push_back({a0, a1, b0});
        t.mesh.faces.push_back({a1, b1, b0});
      } else {
        t.mesh.faces.push_back({a0, b1, b0});
        t.mesh.faces.push_back({a0, a1, b1});
      }
    }
  for (int k = 0; k < m; ++k) {
    t.lower.push_back(k);
    t.upper.push_back(rings * m + k);
  }
  return t;
}

// Open parts: the harmonic field (one factorisation) and the distance from the bottom edge,
// whose Dirichlet half on the free top edge costs a third factorisation at the first compute().
void benchmarkTube(double r, double height, double faces)
{
  const double edge = std::sqrt(4.0 * 2.0 * M_PI * r * height / (std::sqrt(3.0) * faces));
  const Tube t = makeTube(r, height, edge);
  std::printf("\nOpen tube R = %.0f mm, H = %.0f mm: %zu vertices, %zu triangles; load average %s\n", r,
              height, t.mesh.vertices.size(), t.mesh.faces.size(), loadAverage().c_str());
  std::vector<Row> rows;
  {
    Row row;
    resetPeakRss();
    const auto start = Clock::now();
    const std::vector<double> u = spira::harmonicField(t.mesh, t.lower, t.upper);
    row.seconds = since(start);
    row.peakMiB = peakRssMiB();
    double worst = 0.0;
    for (size_t v = 0; v < u.size(); ++v)
      worst = std::max(worst, std::abs(u[v] - t.mesh.vertices[v].z() / height));
    char buf[128];
    std::snprintf(buf, sizeof buf, "max |u - z/H| = %.1e", worst);
    row.name = "(d) Spira harmonicField (0 bottom, 1 top)";
    row.detail = buf;
    rows.push_back(row);
  }
  {
    Row row;
    resetPeakRss();
    const auto start = Clock::now();
    spira::HeatDistanceSolver solver(t.mesh);
    const std::vector<double> phi = solver.compute(t.lower);
    row.seconds = since(start);
    row.peakMiB = peakRssMiB();
    const double h = solver.meanEdgeLength();
    double mean = 0.0, worst = 0.0;
    int count = 0;
    for (size_t v = 0; v < phi.size(); ++v) {
      const double z = t.mesh.vertices[v].z();
      if (z <= 5.0 * h) continue;
      const double e = std::abs(phi[v] - z) / z;
      mean += e;
      worst = std::max(worst, e);
      ++count;
    }
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "distance = z: mean %.4f%%, max %.4f%%; %d Dirichlet vertices; compute %.2f s",
                  100.0 * mean / std::max(count, 1), 100.0 * worst, solver.lastStats().dirichletVertices,
                  solver.lastStats().seconds);
    row.name = "(a) Spira distance from the bottom edge";
    row.detail = buf;
    rows.push_back(row);
  }
  printRows(rows);
}

}  // namespace

int main(int argc, char** argv)
{
  const double r = 60.0;
  // Equilateral triangles of edge e: F = 2 pi R^2 / (sqrt(3)/4 e^2).
  const auto edgeFor = [r](double faces) { return r * std::sqrt(8.0 * M_PI / (std::sqrt(3.0) * faces)); };
  bool cgal = true;
  int repeats = 1;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--no-cgal") cgal = false;
    if (arg == "--repeat" && k + 1 < argc) repeats = std::max(1, std::atoi(argv[++k]));
  }
  std::printf(
      "bench_field [--no-cgal] [--repeat N]: times are wall-clock seconds; errors are relative to\n"
      "R * elevation angle on vertices more than 5 mean edges from the base; peak = VmHWM during the row.\n");
  benchmark(r, edgeFor(1.0e6), cgal, repeats);
  benchmark(r, edgeFor(1.0e5), cgal, repeats);
  benchmark(r, edgeFor(1.0e5), cgal, repeats, 0.3);
  benchmarkTube(r, 2.0 * r, 1.0e6);
  return 0;
}
