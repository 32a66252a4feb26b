// The driven gas's kicks (simulate/engine/driving.h): every kick leaves the
// total momentum zero to round-off, in every dimension and for every model
// that can be driven; the kicks bring in the power they are given; and the
// symmetry of hard spheres with constant restitution holds bit for bit:
// velocities ×2 and power ×8 is the same trajectory at half the times.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "common/error.h"
#include "simulate/engine/driving.h"
#include "simulate/run/engine_factory.h"
#include "simulate/start/initial_state.h"
#include "tests/support/saved_state.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

constexpr std::int64_t kNoBudget = std::int64_t(1) << 40;

// A driven engine of scene `s` (its own [driving] left out), its kicks logged.
struct Driven {
  Driven(const Scene& s, const Particles& start, double power, double period = 0.5)
      : engine(make_engine(s, start, 0.0), {.power = power, .period = period, .seed = 77, .geometry = s.geometry()}) {
    engine.record_kicks(&kicks);
  }
  std::vector<KickRecord> kicks;
  DrivenEngine engine;
};

Scene scene_in(CollisionModel model, int dimension) {
  Scene s = test::in_dimension(test::inelastic_scene(600, 0.1, 0.7, 0.0, 5), dimension);
  s.model = model;
  // Each parameter at its typical value, one whose effect can be off (beta) off: smooth particles.
  for (const ModelParameter* p : collision_models().at(std::size_t(model)).parameters)
    s.set_parameter(p->name, p->off ? *p->off : p->example);
  s.equilibrate = 0;
  return s;
}

// Round-off of a sum of N velocities of size v: far below a single
// unremoved mean of N Gaussian increments (≈ √N s).
double round_off(std::size_t n, double energy) { return 64 * std::numeric_limits<double>::epsilon() * double(n) * std::sqrt(2 * energy); }

TEST(Driving, EveryKickLeavesTheTotalMomentumZero) {
  for (const CollisionModel model : {CollisionModel::kElastic, CollisionModel::kInelastic, CollisionModel::kViscoelastic})
    for (const int d : {1, 2, 3}) {
      const Scene s = scene_in(model, d);
      const Particles start = initial_state(s);
      Driven driven(s, start, 0.2);
      driven.engine.run_until(20, kNoBudget, nullptr);
      ASSERT_GT(driven.kicks.size(), 10u) << model_name(model) << " " << d << "D";
      for (const KickRecord& k : driven.kicks)
        for (int a = 0; a < 3; ++a)
          ASSERT_LE(std::fabs(k.momentum[a]), round_off(start.size(), k.energy_after))
              << model_name(model) << " " << d << "D, kick at t = " << k.time << ", axis " << a;
      const EngineFrame f = driven.engine.frame();
      for (const Vec3& v : f.velocity)
        for (int a = d; a < 3; ++a) ASSERT_EQ(v[a], 0.0) << "an axis beyond the dimension moved";
    }
}

// Each kick brings in P (t_k − t_{k−1}) per particle in expectation; the
// sum over 400 kicks, within 4 of its standard deviations (the kicks' cross
// term Σ v·Δv / N, about 15 % of one kick's energy for 600 spheres).
TEST(Driving, TheKicksBringInThePowerGiven) {
  const Scene s = scene_in(CollisionModel::kInelastic, 3);
  const double power = 0.3;
  Driven driven(s, initial_state(s), power);
  driven.engine.run_until(150, kNoBudget, nullptr);
  ASSERT_GT(driven.kicks.size(), 400u);
  double brought = 0, expected = 0, variance = 0, previous = 0;
  for (const KickRecord& k : driven.kicks) {
    const double jump = k.energy_after - k.energy_before, mean = power * (k.time - previous);
    brought += jump;
    expected += mean;
    // The cross term's variance: Σ (v_i·Δv_i)² / N² ≈ 2 E s² / N, s² = 2 mean / 3 · N/(N−1).
    variance += 2 * k.energy_before * (2 * mean / 3) / double(s.N);
    previous = k.time;
  }
  EXPECT_NEAR(brought / expected, 1.0, 4 * std::sqrt(variance) / expected);
}

// Hard spheres with constant restitution (δ = 0) have no velocity scale of
// their own: velocities ×2 with power ×8 must be the same trajectory at half
// the times (the kick period is in collision times, which halve), exactly,
// since every operation scales by powers of 2. Hence the steady state's T
// scales as power^(2/3), exactly: 8 times the power, 4 times the temperature.
TEST(Driving, EightTimesThePowerIsTheSameGasTwiceAsFast) {
  for (const int d : {3, 2}) {
    const Scene s = scene_in(CollisionModel::kInelastic, d);
    const Particles start = initial_state(s);
    Particles fast = start;
    for (Vec3& v : fast.v) v = {2 * v.x, 2 * v.y, 2 * v.z};
    // A power whose T_P (driving.h) is below the gas's temperature all along.
    const double power = 0.02 * initial_temperature(s);
    Driven slow_gas(s, start, power), fast_gas(s, fast, 8 * power);
    slow_gas.engine.run_until(60, kNoBudget, nullptr);
    fast_gas.engine.run_until(30, kNoBudget, nullptr);
    ASSERT_GT(slow_gas.kicks.size(), 50u);
    ASSERT_EQ(fast_gas.kicks.size(), slow_gas.kicks.size());
    for (std::size_t k = 0; k < slow_gas.kicks.size(); ++k) {
      ASSERT_EQ(2 * fast_gas.kicks[k].time, slow_gas.kicks[k].time) << "kick " << k;
      ASSERT_EQ(fast_gas.kicks[k].energy_after, 4 * slow_gas.kicks[k].energy_after) << "kick " << k;
    }
    const EngineFrame a = slow_gas.engine.frame(), b = fast_gas.engine.frame();
    EXPECT_EQ(a.collisions, b.collisions);
    for (std::size_t i = 0; i < a.position.size(); ++i)
      for (int x = 0; x < 3; ++x) {
        ASSERT_EQ(a.position[i][x], b.position[i][x]) << d << "D, particle " << i;
        ASSERT_EQ(2 * a.velocity[i][x], b.velocity[i][x]) << d << "D, particle " << i;
      }
  }
}

// A restored driven engine goes on with the same kicks (the contract test
// holds it to the same events): a schedule that cannot be is refused.
TEST(Driving, AScheduleOutOfTimeIsRefused) {
  const Scene s = scene_in(CollisionModel::kInelastic, 3);
  const Particles start = initial_state(s);
  auto plain = make_engine(s, start, 0.0);
  plain->run_until(5, kNoBudget, nullptr);
  const Driving driving{.power = 0.2, .period = 0.5, .seed = 77, .geometry = s.geometry()};
  const StateReader forged = test::saved_state_of([&](StateWriter& out) {
    plain->save(out);
    out.put_value("driving/schedule", KickSchedule{.previous = 6, .next = 7, .kicks = 3});  // the last kick after now
  });
  try {
    DrivenEngine restored(restore_engine(s, forged), driving, forged);
    FAIL() << "a last kick after now was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("driving/schedule"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace coolgas
