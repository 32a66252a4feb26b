// Haff's law for the homogeneous cooling state: T(t) = T0 / (1 + t/t0)^2 with
// t0 = 6 / ((1 - r^2) omega0) and omega0 = 1 in this project's units
// (tests/physics/README.md; Haff, J. Fluid Mech. 134, 401 (1983)). Tested with r
// near 1 in a small dilute box, where the homogeneous state is stable, and
// checked to have stayed homogeneous: the collision rate must follow the
// Enskog omega ∝ sqrt(T), i.e. omega(t) = 1 / (1 + t/t0).
#include <gtest/gtest.h>

#include "tests/support/kinetic_theory.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

TEST(HaffLaw, TemperatureAndCollisionRateFollowTheHomogeneousCooling) {
  const double r = 0.98;
  test::expect_haff_cooling(test::inelastic_scene(4000, 0.05, r, 0.0, 31), 6.0 / (1.0 - r * r));  // t0 about 152
}

}  // namespace
}  // namespace coolgas
