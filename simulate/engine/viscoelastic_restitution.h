// The coefficient of normal restitution of viscoelastic spheres
// (Brilliantov, Spahn, Hertzsch, Pöschel, PRE 53, 5382 (1996)): Hertz's
// elastic force plus a dissipative force proportional to the rate of
// deformation. For the compression ξ of two spheres,
//     m_eff ξ'' = −ρ (ξ^{3/2} + (3/2) A √ξ ξ'),   ξ(0) = 0, ξ'(0) = g,
// and ε = −ξ'(end)/g with "end" the return to ξ = 0. In reduced form ε
// depends on one number, x = b g^{1/5} (b = A α^{2/5} with α = (3/2)^{3/2} ρ /
// m_eff in the notation of Schwager & Pöschel, PRE 57, 650 (1998)):
//     η'' = −η^{3/2} − x √η η',   η(0) = 0, η'(0) = 1,   ε(x) = −η'(end).
// Its expansion is Schwager & Pöschel's series (confirmed by Ramírez,
// Pöschel, Brilliantov, Schwager, PRE 60, 4465 (1999)):
//     ε = 1 − C1 x + C2 x² ∓ …,  C1 = Γ(3/5)√π / (2^{1/5} 5^{2/5} Γ(21/10)) = 1.15344,
//                                C2 = (3/5) C1² = 0.79826,
// which diverges beyond x ≈ 1 (ε(1) = 0.33; the two-term series gives 0.64).
// So ε is not taken from the series at all: the reduced equation is solved
// once per process (fourth-order Runge–Kutta) on a grid of x and
// interpolated; the series is what the tests check it against. Beyond
// kMaxX (ε < 2e-4, practically sticky) ε is held at ε(kMaxX).
#pragma once
#include <vector>

namespace coolgas {

// Schwager & Pöschel's first two coefficients (closed forms above).
inline constexpr double kViscoelasticC1 = 1.1534489;
inline constexpr double kViscoelasticC2 = 0.7982666;

// b of a pair of spheres of one material, radii a1, a2 and masses m1, m2, from
// b of two spheres of diameter 1 and mass 1 (a mixture's [[species]]): b =
// A α^{2/5} with α ∝ √R_eff / m_eff (R_eff = a1 a2 / (a1 + a2), m_eff =
// m1 m2 / (m1 + m2); Brilliantov et al. 1996), so b ∝ R_eff^{1/5} m_eff^{-2/5},
// and the unit pair has R_eff = 1/4, m_eff = 1/2. Disks and rods take the
// spheres' law (their restitution is the spheres' ε at any d).
double viscoelastic_pair_b(double b, double a1, double a2, double m1, double m2);

// ε(x) from the reduced equation of motion, solved now (slow: ~1 ms).
double viscoelastic_restitution_exact(double x);

// ε(x) tabulated on a grid in x and interpolated by cubic Lagrange
// polynomials; built once, on first use (~1 s). Within 2e-7 of an
// independent solution (measured 1.82e-7 at x = 0.70, on a grid of
// 0.00025 over [0, 8]: tests/physics/viscoelastic_table_accuracy.py). The
// error is the fixed-step solution's own (its end is found by a linear
// interpolation within the last step), which the interpolation carries; a
// better solution would change every viscoelastic run's numbers, so the
// bound is stated instead.
class ViscoelasticTable {
 public:
  static constexpr double kMaxX = 8.0;
  static const ViscoelasticTable& get();
  double operator()(double x) const;

 private:
  ViscoelasticTable();
  static constexpr int kKnotsPerUnit = 64;
  std::vector<double> eps_;  // ε at x = k / kKnotsPerUnit, k = -1 .. kMaxX kKnotsPerUnit + 2
};

}  // namespace coolgas
