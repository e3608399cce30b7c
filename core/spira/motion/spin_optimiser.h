#pragma once

#include <vector>

#include "spira/base/progress.h"
#include "spira/motion/motion_layers.h"
#include "spira/motion/spin_cost.h"

namespace spira {

// The spin of one layer: the chart value (motion_frames.h) is c(x) = sum_i a_i x^i over the
// layer's abscissa x (motion_layers.h), so the tool_frame.h spin at point m is
// frames.chartOffset[m] + c(x_m).
struct LayerSpinSolution {
  std::vector<double> coefficients;  // a_0 .. a_n, rad
  // Over the layer's full set of points: Phi of its segments, the one into the next layer's first
  // point included (so the layers' objectives add up to the plan's), and its constraint penalty.
  double objective = 0.0;
  double penalty = 0.0;
  bool polished = false;          // re-optimised on every point after the subsample search
  int evaluations = 0;            // poses solved
  std::vector<SolvedPose> poses;  // the layer's points, in order
};

// Evaluates a polynomial sum_i a_i x^i.
double evaluateSpinPolynomial(const std::vector<double>& coefficients, double x);

// Layer-wise optimisation of the torch spin (Chalvin 2020, ch. 4, Fig. 4.1): for each layer, the
// polynomial coefficients that minimise SpinCost's objective plus penalties, searched by
// Levenberg-Marquardt on a subsample of the layer, then checked (and polished if a constraint
// breaks between samples) on all of its points. Layers are solved in path order; each starts
// with the spin the previous one ended with (continuity: the transition is a normal step) and
// from its coefficients (warm start). The starting guesses also include the constant chart spin
// and the spin that follows the travel direction; the first layer scans its start value around
// the full turn. An accepted step never raises the cost, so a layer is never worse than its best
// starting guess on its subsample.
class SpinOptimiser {
 public:
  SpinOptimiser(const SpinCost& cost, const MotionParams& params);

  // One layer. `initial` holds a_0..a_k (cut or padded with zeros to the layer's degree); with
  // `startFixed` a_0 is held, else the start is searched too. `entry`: the joints before the layer
  // (the previous point, or the seed), for the 2 pi branches of its first point.
  LayerSpinSolution optimiseLayer(const MotionLayer& layer, std::vector<double> initial, bool startFixed,
                                  const JointVector& entry) const;

  // Every layer in order. `startChartSpin`: a starting guess for the first layer's start value.
  std::vector<LayerSpinSolution> optimisePath(const std::vector<MotionLayer>& layers, const JointVector& seed,
                                              double startChartSpin, Progress& progress) const;

  // The chart spin of every point of `layers` (size: their total count).
  static std::vector<double> chartSpins(const std::vector<MotionLayer>& layers,
                                        const std::vector<LayerSpinSolution>& solutions);

 private:
  struct Samples {
    std::vector<size_t> positions;  // in the layer; `count` stands for the next layer's first point
    std::vector<double> x;
  };
  Samples samples(const MotionLayer& layer, size_t wanted) const;
  // Solves the samples at coefficients `a`; fills kResidualsPerPoint residuals per sample.
  void evaluate(const MotionLayer& layer, const Samples& s, const std::vector<double>& a,
                const JointVector& entry, Eigen::VectorXd& residuals, std::vector<SolvedPose>* poses) const;
  std::vector<double> travelFit(const MotionLayer& layer, int degree) const;

  const SpinCost& cost_;
  const MotionParams& params_;
};

}  // namespace spira
