// The plan of a run (simulate/run/run_plan.h): a pilot of the scene fed to
// the run's own ETA rule.
#include "simulate/run/run_plan.h"

#include <gtest/gtest.h>

#include <csignal>
#include <string>

#include "common/error.h"
#include "common/interrupt.h"
#include "simulate/run/models.h"
#include "simulate/run/run_costs.h"
#include "simulate/run/engine_factory.h"
#include "simulate/run/time_grid.h"
#include "simulate/start/initial_state.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

// An elastic gas collides at the Enskog rate, one collision per particle
// per time unit (two particles a collision), for ever, in every dimension:
// a pilot of 1e4 of 4e4 particles, extrapolated at its own exponent, plans
// N t_end / 2 collisions to t_end = 1000 (within the 2 % of the collision
// rate test, tests/physics/collision_rate_test.cc).
TEST(RunPlan, AnElasticGasCollidesAtTheEnskogRate) {
  for (int d = 1; d <= 3; ++d) {
    Scene s = test::in_dimension(test::elastic_scene(40000, 0.208, 3), d);
    s.t_end = 1000;
    const RunPlan plan = plan_run(s, nullptr);
    EXPECT_NEAR(plan.collisions / (double(s.N) * s.t_end / 2), 1.0, 0.02) << d << "D";
    EXPECT_EQ(plan.N, s.N);
    EXPECT_EQ(plan.L, s.L);
  }
}

// A driven gas (simulate/engine/driving.h) whose power holds it at T0
// (P = (1 - r0^2) T0 / 2, the energy balance of tests/physics/driven_gas_test.cc)
// collides at the rate of t = 0 for ever: N t_end / 2 collisions to
// t_end = 1000, within 3 % (its steady T lies about 1 % above T0 at
// r0 = 0.8, its rate half that; the pilot's relaxation the rest), where a
// cooling gas's rule would plan a fraction of them.
TEST(RunPlan, ADrivenGasCollidesAtItsSteadyRate) {
  Scene s = test::inelastic_scene(40000, 0.1, 0.8, 0.0, 3);
  s.t_end = 1000;
  s.driving_power = (1 - 0.8 * 0.8) / 2;  // holds the gas near T0
  const RunPlan plan = plan_run(s, nullptr);
  EXPECT_NEAR(plan.collisions / (double(s.N) * s.t_end / 2), 1.0, 0.03);
}

// A run no larger than the pilot and no longer than its time is its own
// pilot: the plan's collisions are the run's, exactly (same seed, same
// events); its dumps are the time grid's and t = 0; its memory the engine's
// bytes per particle.
TEST(RunPlan, ASmallShortRunIsItsOwnPilot) {
  Scene s = test::inelastic_scene(4000, 0.208, 0.1, 1e-4, 5);
  s.t_end = 50;
  const RunPlan plan = plan_run(s, nullptr);
  auto engine = make_engine(s, initial_state(s), 0.0);
  engine->run_until(s.t_end, std::int64_t(1) << 40, nullptr);
  EXPECT_EQ(plan.collisions, double(engine->counters().collisions));
  int dumps = 1;
  for (const StopTime& stop : stop_times(s)) dumps += stop.dump;
  EXPECT_EQ(plan.dumps, dumps);
  EXPECT_EQ(plan.peak_bytes, double(s.N) * kBytesPerParticle);
}

// Ballistic aggregation merges at most N - 1 times.
TEST(RunPlan, AggregationMergesAtMostNMinusOneTimes) {
  Scene s = test::elastic_scene(20000, 0.208, 2);
  s.model = CollisionModel::kAggregation;
  s.t_end = 1e4;
  const RunPlan plan = plan_run(s, nullptr);
  EXPECT_LE(plan.collisions, double(s.N - 1));
  EXPECT_GT(plan.collisions, 0.9 * double(s.N));  // mean field: N (1 + t/tau)^-6/5 left, tau of order 1
}

// Issue 52, class 4: system.equilibrate = 1e7 was simulated whole by the
// pilot (5e10 collisions of its 10^4 particles). The pilot equilibrates for
// kPilotEquilibrate collision times at most, so its collisions are those of
// the same scene at the default 5; the run's equilibration is in the CPU
// time, analytically (equilibrate x N / 2 collisions at the run's rate).
TEST(RunPlan, ALongEquilibrationIsPricedNotSimulatedByThePilot) {
  Scene s = test::inelastic_scene(40000, 0.208, 0.1, 1e-4, 5);
  s.t_end = 1000;
  ASSERT_EQ(s.equilibrate, kPilotEquilibrate);
  const RunPlan usual = plan_run(s, nullptr);
  s.equilibrate = 1e7;
  const RunPlan plan = plan_run(s, nullptr);
  EXPECT_EQ(plan.collisions, usual.collisions);
  const ModelCosts& costs = *model_row(s.model).costs;
  EXPECT_EQ(plan.cpu_seconds, costs.cpu_seconds(s, plan.collisions));
  Scene short_one = s;
  short_one.equilibrate = kPilotEquilibrate;
  EXPECT_NEAR(plan.cpu_seconds - usual.cpu_seconds,
              costs.cpu_seconds(s, 0) - costs.cpu_seconds(short_one, 0), 1e-9 * plan.cpu_seconds);
  EXPECT_GT(plan.cpu_seconds, 1e3 * usual.cpu_seconds);  // 2e11 collisions against 1e8
}

// A signal during the pilot's set-up (placement, equilibration) is the
// normal interrupted stop (exit code 3), never "internal error".
// Rough and mixture collisions are priced at their measured costs (W1R and
// W1M against W1, tests/bench/README.md): the same work costs 1.06 and
// 1/0.77 times the smooth equal spheres' (the set-up left out).
TEST(RunPlan, RoughAndMixtureCollisionsCostTheirMeasuredShare) {
  Scene s = test::inelastic_scene(40000, 0.208, 0.5, 1e-4, 5);
  s.equilibrate = 0;
  const ModelCosts& costs = *model_row(s.model).costs;
  const double smooth = costs.cpu_seconds(s, 1e9);
  EXPECT_NEAR(costs.cpu_seconds(test::rough(s, 0.5), 1e9) / smooth, 1.06, 1e-12);
  EXPECT_NEAR(costs.cpu_seconds(test::binary_mixture(s, 0.5, 1.5), 1e9) / smooth, 1 / 0.77, 1e-12);
}

TEST(RunPlan, APilotInterruptedInItsSetUpThrowsInterrupted) {
  Scene s = test::inelastic_scene(40000, 0.208, 0.1, 1e-4, 5);
  s.equilibrate = 1e7;
  s.t_end = 1000;
  const volatile std::sig_atomic_t flag = SIGINT;
  try {
    plan_run(s, &flag);
    FAIL() << "not interrupted";
  } catch (const Interrupted& e) {
    EXPECT_EQ(e.signal, SIGINT);
    EXPECT_EQ(std::string(e.what()),
              "interrupted by SIGINT in the set-up of the pilot run of --estimate; nothing written");
  }
}

TEST(RunPlan, AStartFromAFileIsRefused) {
  Scene s = test::elastic_scene(1000, 0.2);
  s.init = InitialPositions::kFile;
  EXPECT_THROW(plan_run(s, nullptr), InputError);
}

}  // namespace
}  // namespace coolgas
