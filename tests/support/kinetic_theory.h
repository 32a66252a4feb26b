// Checks of a gas against kinetic theory shared by the 3D and the 2D
// physics tests (tests/physics/README.md): the collision frequency at the
// start, and Haff's homogeneous cooling with the dimension's own t0.
#pragma once
#include <gtest/gtest.h>

#include <cmath>

#include "simulate/run/engine_factory.h"
#include "simulate/start/initial_state.h"

namespace coolgas::test {

// Collisions per particle per unit time over 0 < t < 1, from the scene's start.
inline double initial_collision_rate(const Scene& s) {
  auto e = make_engine(s, initial_state(s), 0.0);
  e->run_until(1.0, std::int64_t(1) << 40, nullptr);
  return 2.0 * double(e->counters().collisions) / double(s.N) / 1.0;
}

// T(t) = T0 / (1 + t/t0)^2 at t0/2, t0 and 2 t0, within 2 % (the velocity
// distribution's a2 changes the rate by < 0.3 % at r = 0.98, the rest is the
// statistics of a few thousand particles); and the gas stayed homogeneous:
// its collision rate followed the Enskog omega ∝ sqrt(T) = 1 / (1 + t/t0)
// within 3 %.
inline void expect_haff_cooling(const Scene& s, double t0) {
  auto e = make_engine(s, initial_state(s), 0.0);
  const double e0 = e->observables().kinetic_energy;
  double t_prev = 0;
  std::int64_t c_prev = 0;
  for (double t : {0.5 * t0, t0, 2.0 * t0}) {
    e->run_until(t, std::int64_t(1) << 40, nullptr);
    const double haff = 1.0 / ((1 + t / t0) * (1 + t / t0));
    EXPECT_NEAR(e->observables().kinetic_energy / e0 / haff, 1.0, 0.02) << "t = " << t;
    // Mean collision rate over (t_prev, t]: ∫ dt/(1 + t/t0) / (t - t_prev).
    const double expected = t0 * std::log((1 + t / t0) / (1 + t_prev / t0)) / (t - t_prev);
    const double measured = 2.0 * double(e->counters().collisions - c_prev) / double(s.N) / (t - t_prev);
    EXPECT_NEAR(measured / expected, 1.0, 0.03) << "t = " << t;
    t_prev = t;
    c_prev = e->counters().collisions;
  }
}

}  // namespace coolgas::test
