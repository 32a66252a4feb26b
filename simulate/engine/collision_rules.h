// Collision rules: what happens to the normal relative velocity when two
// spheres touch. The engine is a template over the rule, so a scene pays only
// for the rule it names (an elastic scene runs no inelastic code at all).
//
// A rule is a small struct with
//   static constexpr bool kDissipative;      // can energy be lost? (enables collapse detection)
//   double restitution(double g, bool& below_delta) const;
//   int collapse_limit() const;              // (dissipative rules) see engine.cc
//   static constexpr bool kRough;            // do collisions turn the particles' spins? (RoughRule)
//   static constexpr bool kMixture;          // do particles differ in size and mass? (MixtureRule,
//                                            // whose restitution(g, a, b, below_delta) is a pair's)
// where g > 0 is the normal relative speed before the collision; it returns
// the coefficient of restitution r and sets below_delta when the collision
// was made elastic by the δ cut-off. Adding a rule: a struct here, one line
// at the end of engine.cc, and its model's rows (ARCHITECTURE.md).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "simulate/engine/viscoelastic_restitution.h"

namespace coolgas {

struct ElasticRule {
  static constexpr bool kDissipative = false;
  static constexpr bool kRough = false;
  static constexpr bool kMixture = false;
  double restitution(double /*g*/, bool& below_delta) const {
    below_delta = false;
    return 1.0;
  }
};

// The paper's scheme (Eq. 1 with the cut-off of Ben-Naim et al. 1999):
// r = r0, except r = 1 when the normal relative speed is below δ.
struct ConstantRestitutionRule {
  static constexpr bool kDissipative = true;
  static constexpr bool kRough = false;
  static constexpr bool kMixture = false;
  double r0 = 1.0;
  double delta = 0.0;
  double restitution(double g, bool& below_delta) const {
    below_delta = g < delta;
    return below_delta ? 1.0 : r0;
  }
  // Collisions of one particle in a row without time advancing that count as
  // inelastic collapse. Without a cut-off nothing bounds the relative speed
  // from below: a few hundred such collisions are collapse (three spheres with
  // r0 = 0.05 go on for ~800 until the speeds underflow to zero). With
  // delta > 0 the relative speed stays above ~r0 delta and clusters in
  // contact can resolve thousands of same-instant collisions (seen with
  // r0 = 0.1, delta = 1e-7), so only a far longer run means a hang.
  int collapse_limit() const { return delta > 0 ? 60000 : 200; }
};

// Viscoelastic spheres (simulate/engine/viscoelastic_restitution.h): r = ε(b g^{1/5}),
// which rises to 1 as the normal speed g goes to 0, so slow collisions are
// nearly elastic and inelastic collapse cannot happen; δ (default 0) may
// still make the slowest collisions exactly elastic. b is in (σ ω0)^{-1/5}.
struct ViscoelasticRule {
  static constexpr bool kDissipative = true;
  static constexpr bool kRough = false;
  static constexpr bool kMixture = false;
  ViscoelasticRule(double b_, double delta_) : b(b_), delta(delta_), eps(&ViscoelasticTable::get()) {}
  double b;
  double delta;
  const ViscoelasticTable* eps;
  double restitution(double g, bool& below_delta) const {
    below_delta = g < delta;
    return below_delta ? 1.0 : (*eps)(b * std::pow(g, 0.2));
  }
  // Collapse is impossible (ε -> 1 as g -> 0), but dense clusters resolve
  // thousands of near-simultaneous collisions: only a far longer run is a hang.
  int collapse_limit() const { return 60000; }
};

// Rough spheres (collision.beta > -1): the normal rule's restitution (any
// of the three above), and the tangential relative velocity of the contact
// points reversed and scaled by beta (pair_prediction.h,
// apply_tangential_restitution), which turns the spins. An engine of this rule keeps an angular velocity per particle;
// smooth scenes never instantiate it, so their hot loop is as before. The
// tangential part cannot collapse a gas (the normal speeds are the normal
// rule's), so collapse detection is the normal rule's.
template <class Normal>
struct RoughRule : Normal {
  static constexpr bool kRough = true;
  // beta in [-1, 1], q = I / (m a^2) in (0, 1].
  RoughRule(const Normal& normal, double beta_, double q_)
      : Normal(normal),
        beta(beta_),
        inertia(q_),
        eta_t(q_ * (1.0 + beta_) / (2.0 * (1.0 + q_))),
        spin_turn((1.0 + beta_) / (1.0 + q_)) {}
  double beta, inertia;
  double eta_t;      // the tangential impulse per unit tangential speed (unit masses)
  double spin_turn;  // each spin's change per unit of n x g_t
};

// A mixture of sizes and masses (the scene's [[species]]): the normal rule's
// restitution between particles of species a and b, touching at the
// distance (sigma_a + sigma_b) / 2 and exchanging momentum in proportion to
// their masses (pair_prediction.h, apply_restitution_with_masses). A
// constant r0 is every pair's; viscoelastic spheres' b is the pair's own
// (viscoelastic_pair_b), one rule per pair of species. An engine
// of this rule keeps a species per particle, an array beside the records
// that only its partner search reads; equal spheres never instantiate it,
// so their hot loop is as before. Species are numbered from 0 (a byte: the
// scene allows 16).
template <class Normal>
struct MixtureRule : Normal {
  static constexpr bool kMixture = true;
  static constexpr bool kPairRestitution = std::is_same_v<Normal, ViscoelasticRule>;
  MixtureRule(const Normal& normal, std::vector<double> diameter, std::vector<double> mass_)
      : Normal(normal), radius(diameter.size()), mass(std::move(mass_)) {
    for (std::size_t s = 0; s < diameter.size(); ++s) radius[s] = 0.5 * diameter[s];
    if constexpr (kPairRestitution)
      for (std::size_t a = 0; a < radius.size(); ++a)
        for (std::size_t b = 0; b < radius.size(); ++b) {
          pair.push_back(normal);
          pair.back().b = viscoelastic_pair_b(normal.b, radius[a], radius[b], mass[a], mass[b]);
        }
  }
  std::vector<double> radius;  // half the diameter of each species
  std::vector<double> mass;    // the mass of each species
  std::vector<Normal> pair;    // the rule of species a with b at a * species() + b (viscoelastic only)
  int species() const { return int(radius.size()); }
  // The restitution of a pair of species a and b at normal speed g.
  double restitution(double g, int a, int b, bool& below_delta) const {
    if constexpr (kPairRestitution) return pair[std::size_t(a * species() + b)].restitution(g, below_delta);
    else return Normal::restitution(g, below_delta);
  }
  double largest_diameter() const {
    double d = 0;
    for (const double a : radius) d = std::max(d, 2.0 * a);
    return d;
  }
};

}  // namespace coolgas
