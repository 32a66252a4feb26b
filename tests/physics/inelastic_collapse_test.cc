// Inelastic collapse: three spheres on a line with r below the critical
// 7 - 4 sqrt(3) = 0.0718 (McNamara & Young, Phys. Fluids A 4, 496 (1992))
// collide infinitely often in finite time. With delta = 0 the engine must
// report it (not hang); with delta > 0 collisions below delta are elastic and
// the sequence ends (Ben-Naim et al. 1999).
#include <gtest/gtest.h>

#include "simulate/engine/engine.h"

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

}  // namespace
}  // namespace coolgas
