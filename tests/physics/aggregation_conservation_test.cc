// Ballistic aggregation over a long dense run (phi = 0.3, 10^5 merges, many
// of them chains): no two aggregates overlap, the total mass stays N exactly,
// momentum is conserved, the kinetic energy never increases (a perfectly
// inelastic merge can only lose it), and the observables agree with the
// aggregates themselves.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "simulate/engine/aggregation_engine.h"
#include "simulate/run/engine_factory.h"
#include "simulate/start/initial_state.h"
#include "tests/support/min_distance.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

// The largest overlap σ_ij − |r_ij| over all pairs of present aggregates
// (periodic), found with a cell grid as wide as the largest diameter.
double largest_overlap(const EngineBase& e) {
  const Motion* m = e.motion();
  const double* d = e.diameters();
  double dmax = 0;
  for (std::size_t i = 0; i < e.size(); ++i) dmax = std::max(dmax, d[i]);
  CellGrid grid(e.box(), dmax, e.size());
  for (std::size_t i = 0; i < e.size(); ++i)
    if (e.ids()[i] >= 0) grid.insert(int(i), grid.cell_of(m[i].r.x, m[i].r.y, m[i].r.z));
  double worst = -std::numeric_limits<double>::infinity();
  test::for_each_near_pair(grid, e.size(), e.box(), [&](std::size_t i) { return m[i].r; },
                           [&](std::size_t i, std::size_t j, double r) {
                             worst = std::max(worst, 0.5 * (d[i] + d[j]) - r);
                           });
  return worst;
}

TEST(AggregationConservation, DenseRunOf1e5MergesKeepsMassAndLeavesNoOverlap) {
  Scene s = test::elastic_scene(120000, 0.3, 21);
  s.model = CollisionModel::kAggregation;
  s.equilibrate = 0;  // any hard-sphere packing will do here
  auto e = make_engine(s, initial_state(s), 0.0);
  const Vec3 p0 = summarize_aggregates(*e).momentum;
  double energy = summarize_aggregates(*e).kinetic_energy;
  int chunks = 0;
  while (e->counters().collisions < 100000) {
    e->run_until(e->now() + 0.05, std::int64_t(1) << 40, nullptr);
    const AggregateSummary a = summarize_aggregates(*e);
    ASSERT_LE(a.kinetic_energy, energy * (1 + 1e-13)) << "t = " << e->now();
    energy = a.kinetic_energy;
    ++chunks;
  }
  e->synchronize();
  const AggregateSummary a = summarize_aggregates(*e);
  double mass = 0, largest = 0;
  std::int64_t present = 0;
  for (std::size_t i = 0; i < e->size(); ++i) {
    mass += e->masses()[i];
    largest = std::max(largest, e->masses()[i]);
    present += e->ids()[i] >= 0;
  }
  EXPECT_EQ(mass, 120000.0);  // integer-valued doubles: exact
  EXPECT_EQ(present, a.aggregates);
  EXPECT_EQ(present, 120000 - e->counters().collisions);
  EXPECT_EQ(a.largest_mass, largest);
  EXPECT_EQ(a.mean_mass, 120000.0 / double(present));
  EXPECT_LT(largest_overlap(*e), 1e-10);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(a.momentum[d], p0[d], 1e-10) << d;
  EXPECT_GT(chunks, 10);  // the energy was checked along the way
}

}  // namespace
}  // namespace coolgas
