#include "spira/motion/spin_optimiser.h"

#include <algorithm>
#include <cmath>

#include <Eigen/QR>

#include "spira/base/units.h"
#include "spira/motion/least_squares.h"

namespace spira {

namespace {

constexpr int kStartScan = 24;  // start values tried around the turn for the first layer
constexpr int kP = SpinCost::kResidualsPerPoint;

// The layer's degree: no more coefficients than distinct abscissae beyond the start.
int effectiveDegree(const MotionLayer& layer, int degree)
{
  const int distinct = static_cast<int>(layer.count) - 1 + (layer.hasNext ? 1 : 0);
  return std::max(0, std::min(degree, distinct));
}

}  // namespace

double evaluateSpinPolynomial(const std::vector<double>& coefficients, double x)
{
  double v = 0.0;
  for (auto it = coefficients.rbegin(); it != coefficients.rend(); ++it) v = v * x + *it;
  return v;
}

SpinOptimiser::SpinOptimiser(const SpinCost& cost, const MotionParams& params) : cost_(cost), params_(params)
{
}

SpinOptimiser::Samples SpinOptimiser::samples(const MotionLayer& layer, size_t wanted) const
{
  Samples s;
  const size_t count = layer.count;
  const size_t k = std::min(std::max<size_t>(wanted, 2), count);
  for (size_t i = 0; i < k; ++i) {
    const size_t pos = k == 1 ? 0 : (i * (count - 1) + (k - 1) / 2) / (k - 1);
    if (s.positions.empty() || pos != s.positions.back()) s.positions.push_back(pos);
  }
  if (layer.hasNext) s.positions.push_back(count);
  for (size_t pos : s.positions) s.x.push_back(pos < count ? layer.x[pos] : layer.xNext);
  return s;
}

void SpinOptimiser::evaluate(const MotionLayer& layer, const Samples& s, const std::vector<double>& a,
                             const JointVector& entry, Eigen::VectorXd& residuals,
                             std::vector<SolvedPose>* poses) const
{
  residuals.resize(static_cast<Eigen::Index>(s.positions.size()) * kP);
  if (poses) poses->resize(s.positions.size());
  SolvedPose previous;
  JointVector near = entry;
  const double pointsInLayer = static_cast<double>(layer.count + (layer.hasNext ? 1 : 0));
  for (size_t i = 0; i < s.positions.size(); ++i) {
    const SolvedPose pose =
        cost_.solve(layer.first + s.positions[i], evaluateSpinPolynomial(a, s.x[i]), near);
    const double segments = i == 0 ? 1.0 : static_cast<double>(s.positions[i] - s.positions[i - 1]);
    cost_.residuals(i == 0 ? nullptr : &previous, segments, pose, segments / pointsInLayer,
                    residuals.data() + static_cast<Eigen::Index>(i) * kP);
    near = pose.q;
    previous = pose;
    if (poses) (*poses)[i] = pose;
  }
}

std::vector<double> SpinOptimiser::travelFit(const MotionLayer& layer, int degree) const
{
  // The chart spin that keeps the tool_frame spin constant, c = const - chartOffset, fitted by
  // a polynomial through c(0) = 0.
  std::vector<double> out(static_cast<size_t>(degree) + 1, 0.0);
  if (degree == 0) return out;
  const size_t rows = layer.count + (layer.hasNext ? 1 : 0);
  const std::vector<double>& offset = cost_.frames().chartOffset;
  Eigen::MatrixXd a(static_cast<Eigen::Index>(rows), degree);
  Eigen::VectorXd y(static_cast<Eigen::Index>(rows));
  for (size_t m = 0; m < rows; ++m) {
    const double x = m < layer.count ? layer.x[m] : layer.xNext;
    double p = 1.0;
    for (int i = 0; i < degree; ++i) a(static_cast<Eigen::Index>(m), i) = (p *= x);
    y[static_cast<Eigen::Index>(m)] = offset[layer.first] - offset[layer.first + m];
  }
  const Eigen::VectorXd b = a.colPivHouseholderQr().solve(y);
  for (int i = 0; i < degree; ++i) out[static_cast<size_t>(i) + 1] = b.allFinite() ? b[i] : 0.0;
  return out;
}

LayerSpinSolution SpinOptimiser::optimiseLayer(const MotionLayer& layer, std::vector<double> initial,
                                               bool startFixed, const JointVector& entry) const
{
  LayerSpinSolution out;
  const int degree = effectiveDegree(layer, params_.degree);
  initial.resize(static_cast<size_t>(degree) + 1, 0.0);
  const double start = initial[0];

  // Starting guesses: the warm start, the constant chart spin, the spin that follows the travel.
  std::vector<std::vector<double>> guesses{initial};
  std::vector<double> flat(initial.size(), 0.0);
  flat[0] = start;
  guesses.push_back(flat);
  std::vector<double> travel = travelFit(layer, degree);
  travel[0] = start;
  guesses.push_back(travel);
  if (!startFixed)
    for (int k = 0; k < kStartScan; ++k)
      for (const std::vector<double>* shape : {&flat, &travel}) {
        std::vector<double> g = *shape;
        g[0] = start + 2.0 * kPi * k / kStartScan;
        guesses.push_back(g);
      }

  const Samples search = samples(layer, static_cast<size_t>(params_.searchSamples));
  const Samples full = samples(layer, layer.count);
  const bool subsampled = search.positions.size() < full.positions.size();
  Eigen::VectorXd r;
  size_t best = 0;
  double bestCost = 0.0;
  for (size_t g = 0; g < guesses.size(); ++g) {
    evaluate(layer, search, guesses[g], entry, r, nullptr);
    out.evaluations += static_cast<int>(search.positions.size());
    const double c = r.squaredNorm();
    if (g == 0 || c < bestCost) {
      best = g;
      bestCost = c;
    }
  }

  // Variables: a_1..a_n with the start held, a_0..a_n otherwise.
  const size_t skip = startFixed ? 1 : 0;
  auto toCoefficients = [&](const Eigen::VectorXd& v) {
    std::vector<double> a(initial.size(), start);
    for (Eigen::Index i = 0; i < v.size(); ++i) a[static_cast<size_t>(i) + skip] = v[i];
    return a;
  };
  auto toVariables = [&](const std::vector<double>& a) {
    Eigen::VectorXd v(static_cast<Eigen::Index>(a.size() - skip));
    for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = a[static_cast<size_t>(i) + skip];
    return v;
  };
  auto solveOn = [&](const Samples& s, const std::vector<double>& from, int iterations) {
    LeastSquaresOptions options;
    options.maxIterations = iterations;
    const ResidualFunction f = [&](const Eigen::VectorXd& v, Eigen::VectorXd& res) {
      evaluate(layer, s, toCoefficients(v), entry, res, nullptr);
    };
    const LeastSquaresResult result = minimiseLeastSquares(f, toVariables(from), options);
    out.evaluations += result.evaluations * static_cast<int>(s.positions.size());
    return toCoefficients(result.x);
  };

  std::vector<double> a = guesses[best];
  if (toVariables(a).size() > 0) a = solveOn(search, a, params_.maxIterations);

  // The full layer decides between the search's result and its best guess. If a constraint
  // breaks harder between the samples than at them, the result is polished on every point.
  struct Measured {
    std::vector<double> a;
    double cost = 0.0, penalty = 0.0, worst = 0.0;  // worst: largest penalty residual
    std::vector<SolvedPose> poses;
  };
  auto measure = [&](const Samples& s, const std::vector<double>& coefficients) {
    Measured m;
    m.a = coefficients;
    evaluate(layer, s, coefficients, entry, r, &m.poses);
    out.evaluations += static_cast<int>(s.positions.size());
    m.cost = r.squaredNorm();
    for (Eigen::Index i = 0; i < r.size(); ++i)
      if (i % kP >= SpinCost::kPenalty && i % kP < SpinCost::kCentring) {
        m.penalty += r[i] * r[i];
        m.worst = std::max(m.worst, std::abs(r[i]));
      }
    return m;
  };
  Measured chosen = measure(full, a);
  if (subsampled) {
    Measured guess = measure(full, guesses[best]);
    if (guess.cost < chosen.cost) chosen = std::move(guess);
    const double sampledWorst = measure(search, chosen.a).worst;
    if (chosen.worst > 1.01 * sampledWorst + 1e-9 && toVariables(chosen.a).size() > 0) {
      Measured polished = measure(full, solveOn(full, chosen.a, std::max(2, params_.maxIterations / 4)));
      if (polished.cost < chosen.cost) {
        chosen = std::move(polished);
        out.polished = true;
      }
    }
  }
  a = chosen.a;
  const double penalty = chosen.penalty;
  std::vector<SolvedPose> poses = std::move(chosen.poses);
  out.coefficients = a;
  out.penalty = penalty;
  out.objective = 0.0;
  for (size_t i = 1; i < poses.size(); ++i) out.objective += cost_.objective(poses[i - 1], poses[i]);
  if (layer.hasNext) poses.pop_back();
  out.poses = std::move(poses);
  return out;
}

std::vector<LayerSpinSolution> SpinOptimiser::optimisePath(const std::vector<MotionLayer>& layers,
                                                           const JointVector& seed, double startChartSpin,
                                                           Progress& progress) const
{
  std::vector<LayerSpinSolution> out;
  out.reserve(layers.size());
  std::vector<double> initial{startChartSpin};
  JointVector entry = seed;
  for (size_t k = 0; k < layers.size(); ++k) {
    progress.checkCancel();
    progress.report(static_cast<double>(k) / static_cast<double>(layers.size()), "spin optimisation");
    out.push_back(optimiseLayer(layers[k], initial, k > 0, entry));
    const LayerSpinSolution& s = out.back();
    // Continuity and warm start: the next layer begins where this one ends, with its shape.
    initial = s.coefficients;
    initial[0] = evaluateSpinPolynomial(s.coefficients, layers[k].xNext);
    entry = s.poses.back().q;
  }
  progress.report(1.0, "spin optimisation");
  return out;
}

std::vector<double> SpinOptimiser::chartSpins(const std::vector<MotionLayer>& layers,
                                              const std::vector<LayerSpinSolution>& solutions)
{
  std::vector<double> out;
  for (size_t k = 0; k < layers.size() && k < solutions.size(); ++k)
    for (size_t m = 0; m < layers[k].count; ++m)
      out.push_back(evaluateSpinPolynomial(solutions[k].coefficients, layers[k].x[m]));
  return out;
}

}  // namespace spira
