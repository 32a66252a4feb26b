// The cooling of a dilute viscoelastic gas against kinetic theory.
//
// Brilliantov & Pöschel (PRE 61, 5573 (2000); "Kinetic Theory of Granular
// Gases", Oxford 2004, ch. 8): with ε(g) = 1 − C1 x + C2 x² ∓ …, x = b g^{1/5},
// a homogeneous gas cools as T ∝ t^{-5/3} at late times, not by Haff's
// t^{-2}, because collisions become more elastic as it cools. The exponent
// is reached slowly (x decays only as t^{-1/6}, and the x² term steepens the
// decay at the start), so the test compares with the theory's T(t) itself
// rather than with the asymptote. In the homogeneous cooling state with
// molecular chaos and a Maxwellian velocity distribution (the same
// assumptions as Haff's law, tests/physics/haff_law_test.cc):
//
//   dT/dt = −(ω(T) / 12) ⟨(1 − ε(g)²) g²⟩,   ω(T) = ω0 √(T / T0),
//
// where ⟨·⟩ averages over the normal relative speed g of colliding pairs,
// distributed as g e^{−g²/4T} / (2T) (unit mass), and ω is the collision
// frequency per particle (ω0 = 1: the time unit). With ε = r constant this is
// Haff's dT/dt = −(1 − r²) ω T / 3; to first order in b it gives
// T^{-3/5} linear in t, i.e. the t^{-5/3} law. Here ε(g) is the solved
// contact equation (viscoelastic_restitution.h), so the theory carries every
// order in x and the comparison is limited by the Maxwellian assumption
// (the velocity distribution's a2 is of order 1e-2 for weak dissipation) and
// by the statistics of 4000 particles.
#include <gtest/gtest.h>

#include <cmath>

#include "simulate/engine/viscoelastic_restitution.h"
#include "simulate/run/engine_factory.h"
#include "simulate/start/initial_state.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

// ⟨(1 − ε(g)²) g²⟩ over colliding pairs at temperature T: with u = g²/4T the
// weight is e^{−u} du (Simpson's rule on [0, 40]; e^{−40} is negligible).
double mean_loss(double T, double b) {
  const ViscoelasticTable& eps = ViscoelasticTable::get();
  const int n = 800;
  const double h = 40.0 / n;
  double sum = 0;
  for (int k = 0; k <= n; ++k) {
    const double u = k * h, g = 2 * std::sqrt(T * u);
    const double e = eps(b * std::pow(g, 0.2));
    const double w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    sum += w * (1 - e * e) * g * g * std::exp(-u);
  }
  return sum * h / 3;
}

// T(t) / T0 of the theory above, by fourth-order Runge–Kutta.
double theory_ratio(double T0, double b, double t_end) {
  auto rate = [&](double T) { return -std::sqrt(T / T0) * mean_loss(T, b) / 12.0; };
  const int steps = 400;
  const double h = t_end / steps;
  double T = T0;
  for (int k = 0; k < steps; ++k) {
    const double k1 = rate(T), k2 = rate(T + 0.5 * h * k1), k3 = rate(T + 0.5 * h * k2), k4 = rate(T + h * k3);
    T += h * (k1 + 2 * k2 + 2 * k3 + k4) / 6;
  }
  return T / T0;
}

// E/E0 falls from 1 to about 0.013 by t = 200; measured within 2 % of the
// theory at every checkpoint (0.991, 0.999, 1.020, 1.016).
TEST(ViscoelasticCooling, FollowsTheKineticTheoryOfBrilliantovAndPoeschel) {
  Scene s = test::elastic_scene(4000, 0.02, 41);
  s.model = CollisionModel::kViscoelastic;
  s.set_parameter("viscoelastic_b", 0.1);
  const double T0 = initial_temperature(s);
  auto e = make_engine(s, initial_state(s), 0.0);
  const double e0 = e->observables().kinetic_energy;
  double previous = 1;
  for (double t : {10.0, 30.0, 100.0, 200.0}) {
    e->run_until(t, std::int64_t(1) << 40, nullptr);
    const double measured = e->observables().kinetic_energy / e0;
    const double theory = theory_ratio(T0, s.parameter("viscoelastic_b"), t);
    EXPECT_NEAR(measured / theory, 1.0, 0.03) << "t = " << t;
    EXPECT_LT(theory, previous);
    previous = theory;
  }
}

}  // namespace
}  // namespace coolgas
