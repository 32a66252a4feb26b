// Conservation laws over long runs: elastic energy, momentum (elastic and
// inelastic), and no overlapping pair after 10^6 collisions in a dense
// elastic fluid and in a clustering inelastic gas (the paper's r0 = 0.1).
#include <gtest/gtest.h>

#include <cmath>

#include "simulate/run/engine_factory.h"
#include "simulate/start/initial_state.h"
#include "tests/support/min_distance.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

// Runs until at least `collisions` collisions, checking that every frame's
// positions are wrapped.
void run_collisions(EngineBase& e, std::int64_t collisions) {
  while (e.counters().collisions < collisions) {
    e.run_until(e.now() * 1.2 + 1.0, 1 << 30, nullptr);
    const EngineFrame f = e.frame();
    for (const Vec3& r : f.position)
      for (int d = 0; d < 3; ++d) ASSERT_TRUE(r[d] >= 0 && r[d] < e.box()) << r[d];
  }
}

double momentum_norm(const EngineBase& e) {
  const Vec3 m = e.observables().momentum;
  return std::sqrt(dot(m, m));
}

double energy(const EngineBase& e) { return e.observables().kinetic_energy; }

// Σ|v|: the scale against which momentum round-off is measured.
double speed_sum(const EngineBase& e) {
  double s = 0;
  for (const Vec3& v : e.frame().velocity) s += std::sqrt(dot(v, v));
  return s;
}

double min_pair_distance(const EngineBase& e) { return 1.0 - test::largest_overlap(e.frame().position, e.box()); }

TEST(Conservation, ElasticEnergyToOnePartIn1e12Over1e6Collisions) {
  const Scene s = test::elastic_scene(4000, 0.3, 11);
  auto e = make_engine(s, initial_state(s), 0.0);
  const double e0 = energy(*e);
  const double p0 = speed_sum(*e);
  run_collisions(*e, 1000000);
  EXPECT_NEAR(energy(*e) / e0, 1.0, 1e-12);
  EXPECT_LT(momentum_norm(*e), 1e-12 * p0);
}

TEST(Conservation, InelasticMomentumAndNoOverlapWhileClustering) {
  // The paper's gas: r0 = 0.1, delta = 1e-4, phi = 0.208, clusters within t ~ 10.
  const Scene s = test::inelastic_scene(8000, 0.208, 0.1, 1e-4, 12);
  auto e = make_engine(s, initial_state(s), 0.0);
  const double p0 = speed_sum(*e);
  const double e0 = energy(*e);
  run_collisions(*e, 1000000);
  EXPECT_LT(momentum_norm(*e), 1e-12 * p0);
  EXPECT_LT(energy(*e), 1e-2 * e0);  // it did cool and cluster
  EXPECT_GT(min_pair_distance(*e), 1.0 - 1e-10);
}

TEST(Conservation, NoOverlapInADenseElasticFluid) {
  Scene s = test::elastic_scene(4000, 0.45, 13);
  s.init = InitialPositions::kFcc;  // beyond random sequential addition
  auto e = make_engine(s, initial_state(s), 0.0);
  run_collisions(*e, 1000000);
  EXPECT_GT(min_pair_distance(*e), 1.0 - 1e-10);
}

}  // namespace
}  // namespace coolgas
