// Ballistic aggregation over a long dense run (phi = 0.3, 16,000 merges of
// 20,000 particles, many of them chains): no two aggregates overlap, the total mass stays N exactly,
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

TEST(AggregationConservation, DenseRunKeepsMassAndLeavesNoOverlap) {
  const std::int64_t n = 20000;  // the all-pairs overlap check is O(n^2)
  Scene s = test::elastic_scene(n, 0.3, 21);
  s.model = CollisionModel::kAggregation;
  s.equilibrate = 0;  // any hard-sphere packing will do here
  auto e = make_engine(s, initial_state(s), 0.0);
  const Vec3 p0 = e->observables().momentum;
  double energy = e->observables().kinetic_energy;
  int chunks = 0;
  while (e->counters().collisions < n * 4 / 5) {
    e->run_until(e->now() + 0.02, std::int64_t(1) << 40, nullptr);
    const double now = e->observables().kinetic_energy;
    ASSERT_LE(now, energy * (1 + 1e-13)) << "t = " << e->now();
    energy = now;
    ++chunks;
  }
  const Observables o = e->observables();
  ASSERT_TRUE(o.aggregates.has_value());
  const EngineFrame f = e->frame();
  double mass = 0, largest = 0;
  std::int64_t present = 0;
  for (std::size_t i = 0; i < e->size(); ++i) {
    mass += f.mass[i];
    largest = std::max(largest, f.mass[i]);
    present += f.id[i] >= 0;
  }
  EXPECT_EQ(mass, double(n));  // integer-valued doubles: exact
  EXPECT_EQ(present, o.aggregates->aggregates);
  EXPECT_EQ(present, n - e->counters().collisions);
  EXPECT_EQ(o.aggregates->largest_mass, largest);
  EXPECT_EQ(o.aggregates->mean_mass, double(n) / double(present));
  EXPECT_LT(test::largest_overlap(f.position, e->box(), f.diameter), 1e-10);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(o.momentum[d], p0[d], 1e-10) << d;
  EXPECT_GT(chunks, 10);  // the energy was checked along the way
}

// Disks: areas add, so sum d^2 stays N (to round-off: each merge takes a
// square root), with the same mass, momentum and no-overlap laws.
TEST(AggregationConservation, DisksKeepMassAndAreaAndLeaveNoOverlap) {
  const std::int64_t n = 20000;
  Scene s = test::disk_scene(n, 0.3, 22);
  s.model = CollisionModel::kAggregation;
  s.equilibrate = 0;
  auto e = make_engine(s, initial_state(s), 0.0);
  const Vec3 p0 = e->observables().momentum;
  while (e->counters().collisions < n * 4 / 5) e->run_until(e->now() + 0.05, std::int64_t(1) << 40, nullptr);
  const EngineFrame f = e->frame();
  double mass = 0, area = 0;
  for (std::size_t i = 0; i < e->size(); ++i) {
    mass += f.mass[i];
    area += f.diameter[i] * f.diameter[i];
    if (f.id[i] < 0) continue;
    ASSERT_NEAR(f.diameter[i] * f.diameter[i] / f.mass[i], 1.0, 1e-12) << i;  // d^2 = m, not d^3 = m
    ASSERT_EQ(f.position[i].z, 0.0) << i;
  }
  EXPECT_EQ(mass, double(n));
  EXPECT_NEAR(area / double(n), 1.0, 1e-12);
  EXPECT_LT(test::largest_overlap(f.position, e->box(), f.diameter), 1e-10);
  const Vec3 p = e->observables().momentum;
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(p[d], p0[d], 1e-10) << d;
}

// Rods: lengths add, so every aggregate's length equals its mass exactly
// (integer-valued doubles), and a merged rod spans exactly the two it
// replaces. Run until nothing is left to happen: every pair of aggregates on
// a ring meets unless they move alike, so the run ends with one aggregate,
// after exactly N - 1 merges (it never reaches L/2: the rods cover 0.3 L),
// with the mass N and the momentum (zero: the start removes it) kept.
TEST(AggregationConservation, RodsMergeIntoOneKeepingMassLengthAndMomentum) {
  const std::int64_t n = 2000;
  Scene s = test::rod_scene(n, 0.3, 23);
  s.model = CollisionModel::kAggregation;
  s.equilibrate = 0;
  auto e = make_engine(s, initial_state(s), 0.0);
  const Vec3 p0 = e->observables().momentum;
  double energy = e->observables().kinetic_energy, speeds = 0;
  for (const Vec3& v : e->frame().velocity) speeds += std::abs(v.x);
  bool checked_midway = false;
  while (e->now() < 1e12 && e->counters().collisions < n - 1) {
    e->run_until(e->now() * 2 + 1, std::int64_t(1) << 40, nullptr);
    ASSERT_LE(e->observables().kinetic_energy, energy * (1 + 1e-13)) << "t = " << e->now();
    energy = e->observables().kinetic_energy;
    if (checked_midway || e->counters().collisions < n / 2) continue;
    const EngineFrame f = e->frame();
    EXPECT_LT(test::largest_overlap(f.position, e->box(), f.diameter), 1e-9 * e->box());
    checked_midway = true;
  }
  e->run_until(e->now() * 2 + 1, std::int64_t(1) << 40, nullptr);  // nothing left to happen
  EXPECT_EQ(e->counters().collisions, n - 1);
  const EngineFrame f = e->frame();
  double mass = 0;
  std::int64_t present = 0;
  for (std::size_t i = 0; i < e->size(); ++i) {
    mass += f.mass[i];
    present += f.id[i] >= 0;
    if (f.id[i] < 0) continue;
    EXPECT_EQ(f.diameter[i], f.mass[i]) << i;
    EXPECT_EQ(f.position[i].y, 0.0) << i;
    EXPECT_EQ(f.position[i].z, 0.0) << i;
  }
  EXPECT_EQ(present, 1);
  EXPECT_EQ(mass, double(n));
  EXPECT_TRUE(checked_midway);
  const Vec3 p = e->observables().momentum;
  EXPECT_NEAR(p.x, p0.x, 1e-12 * speeds);
  EXPECT_EQ(p.y, 0.0);
  EXPECT_EQ(p.z, 0.0);
}

}  // namespace
}  // namespace coolgas
