// Haff's law for the homogeneous cooling state: T(t) = T0 / (1 + t/t0)^2 with
// t0 = 6 / ((1 - r^2) omega0) and omega0 = 1 in this project's units
// (tests/physics/README.md; Haff, J. Fluid Mech. 134, 401 (1983)). Tested with r
// near 1 in a small dilute box, where the homogeneous state is stable, and
// checked to have stayed homogeneous: the collision rate must follow the
// Enskog omega ∝ sqrt(T), i.e. omega(t) = 1 / (1 + t/t0).
#include <gtest/gtest.h>

#include "simulate/run/engine_factory.h"
#include "simulate/start/initial_state.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

TEST(HaffLaw, TemperatureAndCollisionRateFollowTheHomogeneousCooling) {
  const double r = 0.98;
  const Scene s = test::inelastic_scene(4000, 0.05, r, 0.0, 31);
  const double t0 = 6.0 / (1.0 - r * r);  // about 152
  auto e = make_engine(s, initial_state(s), 0.0);
  const double e0 = e->observables().kinetic_energy;
  double t_prev = 0;
  std::int64_t c_prev = 0;
  for (double t : {0.5 * t0, t0, 2.0 * t0}) {
    e->run_until(t, std::int64_t(1) << 40, nullptr);
    const double haff = 1.0 / ((1 + t / t0) * (1 + t / t0));
    // Within 2 %: the velocity distribution's a2 changes the rate by < 0.3 %
    // at r = 0.98, the rest is statistics of 4000 particles.
    EXPECT_NEAR(e->observables().kinetic_energy / e0 / haff, 1.0, 0.02) << "t = " << t;
    // Mean collision rate over (t_prev, t]: ∫ dt/(1 + t/t0) / (t - t_prev).
    const double expected = t0 * std::log((1 + t / t0) / (1 + t_prev / t0)) / (t - t_prev);
    const double measured = 2.0 * double(e->counters().collisions - c_prev) / double(s.N) / (t - t_prev);
    EXPECT_NEAR(measured / expected, 1.0, 0.03) << "t = " << t;
    t_prev = t;
    c_prev = e->counters().collisions;
  }
}

}  // namespace
}  // namespace coolgas
