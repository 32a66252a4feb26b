// The time unit: at t -> 0 the measured collision frequency per particle is
// the Enskog value, which the initial temperature makes 1
// (tests/physics/README.md): with the Carnahan–Starling contact value for
// spheres (accurate to well under 1 % below phi = 0.45), with Henderson's
// for disks (system.dimension = 2, phi the area fraction), with the Tonks
// gas's exact g = 1 / (1 - phi) for rods (system.dimension = 1, phi the line
// fraction; their rate 2 n g sqrt(T / (pi m))). Required within 2 % at three
// densities in each dimension.
#include <gtest/gtest.h>

#include "tests/support/density_cases.h"
#include "tests/support/kinetic_theory.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

using test::Density;

class CollisionRate : public ::testing::TestWithParam<Density> {};

TEST_P(CollisionRate, IsOne) {
  const Density d = GetParam();
  const Scene s = test::in_dimension(test::elastic_scene(40000, d.phi, d.seed), d.dimension);
  EXPECT_NEAR(test::initial_collision_rate(s), 1.0, 0.02);
}

INSTANTIATE_TEST_SUITE_P(EveryDimension, CollisionRate,
                         ::testing::Values(Density{3, 0.05, 21}, Density{3, 0.208, 21}, Density{3, 0.35, 21},
                                           Density{2, 0.05, 41}, Density{2, 0.2, 41}, Density{2, 0.35, 41},
                                           Density{1, 0.1, 61}, Density{1, 0.3, 61}, Density{1, 0.5, 61}),
                         test::density_case_name);

}  // namespace
}  // namespace coolgas
