#pragma once

namespace spira {

// Where the transition revolution of the start-up ends.
enum class StartupTransition {
  // h_min -> h, as the thesis's Figs 3.5 and 4.7 show (000_dbb97c2716e10cc3.txt §3.2.4, §4.3). The spiral
  // then climbs
  // S = j_full Δ + h - h_min per revolution whatever the layer step d of the modulated phase, so
  // every seam rises d - S in one segment: 0.1 h at ±10 % when d = h, about 0 when d = h_min.
  ToNominal,
  // The thesis's text instead ("a gap of h between the first and the last point of this layer"):
  // the start-up climbs exactly what a uniform helix of the modulated phase climbs, so the seam is
  // an ordinary step. With c the layer step that phase will use at the seam (the builder passes the
  // mean step of the first and last generatrices; h when unknown), the transition ramp ends at
  // h_T = h_min + c (n - 1) / n - j_full Δ and the constant revolution is laid at c: the climb is
  // c (n - 1) / n and every step around, the seam included, is c / n. Both are clamped to the window
  // (then a small seam step remains). At ±10 % the transition is almost a full ramp.
  UniformHelix,
};

// Start-up and termination revolutions of the spiral (thesis 000_dbb97c2716e10cc3.txt §3.2.4, Table 3.1).
//
// A deposit can never be thinner than h_min, so the spiral cannot start at height 0: the first
// revolution ramps from h_min (first generatrix) to h_max (last generatrix), which leaves a height
// step where the next revolution starts. Each ramp adds Δ = h_max - h_min to the climb of a
// revolution (Eq. 3.2: Δh_j = j Δ). The rule used here (docs/method.md M14) is
//   j_full = max{ j >= 0 : j Δ < h }    full ramps h_min -> h_max
//   one transition ramp h_min -> h_T   (h_T = h by default, see StartupTransition)
//   one constant revolution at h       (at c with UniformHelix)
//   n_steplayer = j_full + 2           (4 + 2 = 6 at ±10 %, Table 3.1)
// With h_T = h, the seam step left for layers of h is g = h_min - j_full Δ, and
// -(h - h_min) < g <= h_max - h: never more than a half-width of the window (0.1 h at ±10 %).
//
// Edge cases:
// - Δ >= h (very wide window): j_full = 0; the start-up is the transition ramp and the constant
//   revolution (n_steplayer = 2).
// - h == h_min with h_T = h: the transition ramp is flat; it is kept so that n_steplayer = j_full + 2.
// - h == h_max with h_T = h: the transition ramp is a full ramp.
// - j Δ within 1e-9 h of h counts as reaching h (Table 3.1 ends the ramps at Δh_5 = h), so the
//   rounding noise of h_max - h_min cannot add or remove a revolution.
//
// The termination is the start-up mirrored (the revolutions in reverse order, each read from the
// last generatrix to the first): one constant revolution at c, one ramp h_T -> h_min, then j_full
// ramps h_max -> h_min (n_endlayer = j_full + 2). The last revolution lies exactly on the end of
// every generatrix, and the seam into the termination is as small as the one out of the start-up:
// startLength(u) + endLength(u) does not depend on u, so the termination removes exactly the climb
// the start-up built. Its later seams grow (0.1 h, 0.3 h ... h_min at ±10 %), as the start-up's
// first seams do, because the last revolution must be flat.
class StartupProfile {
 public:
  // Throws InputError unless 0 < h_min < h_max, h_min <= h <= h_max and all are finite, or when
  // UniformHelix is asked for with fewer than 2 points per revolution. `layerStep` is c above
  // (UniformHelix only; 0 means h).
  StartupProfile(double h, double hMin, double hMax,
                 StartupTransition transition = StartupTransition::ToNominal, int pointsPerRevolution = 0,
                 double layerStep = 0.0);

  double h() const { return h_; }
  double hMin() const { return hMin_; }
  double hMax() const { return hMax_; }
  double transitionTop() const { return hT_; }
  double constantStep() const { return c_; }
  int fullRamps() const { return fullRamps_; }
  int startRevolutions() const { return fullRamps_ + 2; }
  int endRevolutions() const { return fullRamps_ + 2; }

  // Nominal deposit (step along the generatrix, mm) of start-up revolution r in
  // [0, startRevolutions()) at u = i / (n - 1), the place of generatrix i around the part.
  double startStep(int r, double u) const;
  // Same for termination revolution r in [0, endRevolutions()).
  double endStep(int r, double u) const;
  double startLength(double u) const;  // sum of startStep over the start-up
  double endLength(double u) const;    // sum of endStep over the termination
  // Climb of a revolution after the start-up, and the step left at the seam for the constant
  // revolution, c - climb (the modulated phase's seam step is its own step there minus the climb).
  double climb() const { return fullRamps_ * (hMax_ - hMin_) + hT_ - hMin_; }
  double seamStep() const { return c_ - climb(); }

 private:
  double h_, hMin_, hMax_, hT_, c_;
  int fullRamps_ = 0;
};

}  // namespace spira
