// Inelastic collapse: three spheres on a line with r below the critical
// 7 - 4 sqrt(3) = 0.0718 (McNamara & Young, Phys. Fluids A 4, 496 (1992))
// collide infinitely often in finite time. With delta = 0 the engine must
// report it (not hang); with delta > 0 collisions below delta are elastic and
// the sequence ends (Ben-Naim et al. 1999).
#include <gtest/gtest.h>

#include "simulate/engine/engine.h"
#include "simulate/run/engine_factory.h"
#include "simulate/start/initial_state.h"
#include "tests/support/saved_state.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

Particles three_in_a_row() {
  Particles p;
  p.L = 12;
  p.resize(3);
  p.r = {{3.0, 6, 6}, {5.0, 6, 6}, {7.3, 6, 6}};
  p.v = {{1.0, 0, 0}, {0.0, 0, 0}, {-1.0, 0, 0}};
  return p;
}

TEST(InelasticCollapse, ReportedWithoutCutOff) {
  Engine<ConstantRestitutionRule> e(three_in_a_row(), ConstantRestitutionRule{0.05, 0.0}, 0.0);
  try {
    e.run_until(100.0, std::int64_t(1) << 40, nullptr);
    ADD_FAILURE() << "no collapse reported";
  } catch (const RunStopped& stop) {
    EXPECT_EQ(stop.reason, StopReason::kInelasticCollapse);
  }
}

TEST(InelasticCollapse, FiniteWithCutOff) {
  Engine<ConstantRestitutionRule> e(three_in_a_row(), ConstantRestitutionRule{0.05, 1e-3}, 0.0);
  EXPECT_EQ(e.run_until(100.0, std::int64_t(1) << 40, nullptr), RunStatus::kReached);
  EXPECT_EQ(e.now(), 100.0);
  EXPECT_LT(e.counters().collisions, 100);  // a short, finite sequence
  EXPECT_GT(e.counters().below_delta, 0);   // ended by elastic collisions below delta
  // Momentum: 1 + 0 - 1 = 0 exactly at the start.
  EXPECT_NEAR(e.observables().momentum.x, 0.0, 1e-15);
}

// A whole gas stuck at one time: r0 = 1e-13 with delta = 1e-4 at N = 500
// (issue 41) froze simulated time at t = 0.298 while collisions went on at
// 1.6e6/s, undetected: the per-particle counts are reset by the rebuilds
// (every 100 N collisions) before they reach their limit of 60000. The
// window over the gas sees it, at the same event whether the run is sliced
// or not, and a restored engine stops where the original does.
TEST(InelasticCollapse, AGasWhoseTimeStopsIsReportedWhateverTheSlicing) {
  const Scene s = test::inelastic_scene(500, 0.1, 1e-13, 1e-4, 1);
  const Particles start = initial_state(s);
  auto stop_of = [](EngineBase& e, std::int64_t budget) {
    try {
      while (e.run_until(1000.0, budget, nullptr) != RunStatus::kReached) {
      }
    } catch (const RunStopped& stop) {
      EXPECT_EQ(stop.reason, StopReason::kInelasticCollapse);
      return std::make_pair(e.counters().events, stop.time);
    }
    ADD_FAILURE() << "no collapse reported";
    return std::make_pair(std::int64_t(-1), -1.0);
  };
  auto whole = make_engine(s, start, 0.0);
  const auto at = stop_of(*whole, std::int64_t(1) << 40);
  EXPECT_LT(at.second, 1.0);
  auto sliced = make_engine(s, start, 0.0);
  EXPECT_EQ(stop_of(*sliced, 99991), at);
  auto part = make_engine(s, start, 0.0);
  part->run_until(1000.0, at.first / 2, nullptr);
  auto restored = restore_engine(s, test::saved_state(*part));
  EXPECT_EQ(stop_of(*restored, std::int64_t(1) << 40), at);
}

}  // namespace
}  // namespace coolgas
