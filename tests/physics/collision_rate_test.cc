// The time unit: at t -> 0 the measured collision frequency per particle is
// the Enskog value with the Carnahan–Starling contact value, which the
// initial temperature makes 1 (tests/physics/README.md; Enskog+CS is accurate to
// well under 1 % below phi = 0.45). Required within 2 %.
#include <gtest/gtest.h>

#include "simulate/run/engine_factory.h"
#include "simulate/start/initial_state.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

double initial_rate(double phi) {
  const Scene s = test::elastic_scene(40000, phi, 21);
  auto e = make_engine(s, initial_state(s), 0.0);
  e->run_until(1.0, std::int64_t(1) << 40, nullptr);
  return 2.0 * double(e->counters().collisions) / double(s.N) / 1.0;
}

TEST(CollisionRate, IsOneAtPhi005) { EXPECT_NEAR(initial_rate(0.05), 1.0, 0.02); }
TEST(CollisionRate, IsOneAtPhi0208) { EXPECT_NEAR(initial_rate(0.208), 1.0, 0.02); }
TEST(CollisionRate, IsOneAtPhi035) { EXPECT_NEAR(initial_rate(0.35), 1.0, 0.02); }

}  // namespace
}  // namespace coolgas
