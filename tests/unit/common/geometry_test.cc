// common/geometry.h: exact identities of the box, the particles and kinetic
// theory in d = 1, 2 and 3 (the formulas: tests/physics/README.md).
#include "common/geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace coolgas {
namespace {

const Geometry kAll[] = {Geometry(1), Geometry(2), Geometry(3)};

TEST(Geometry, OnlyOneTwoAndThreeAreDimensions) {
  EXPECT_THROW(Geometry(0), std::invalid_argument);
  EXPECT_THROW(Geometry(4), std::invalid_argument);
  EXPECT_FALSE(Geometry::valid(-3));
  for (const Geometry g : kAll) EXPECT_TRUE(Geometry::valid(g.d()));
}

// A unit sphere covers pi/6 of a unit cube, a unit disk pi/4 of a unit
// square, a unit rod all of a unit length; N, L and phi convert into each
// other, and the 3D forms are the ones coolgas always used, to the bit.
TEST(Geometry, BoxParticlesAndCoveredFractionAgree) {
  const double unit[] = {1.0, M_PI / 4, M_PI / 6};
  for (const Geometry g : kAll) {
    SCOPED_TRACE(g.d());
    EXPECT_DOUBLE_EQ(g.covered_fraction(1, 1), unit[g.d() - 1]);
    EXPECT_EQ(g.box_measure(3.0), std::pow(3.0, g.d()));
    const double L = g.box_side_for(20000, 0.45);
    EXPECT_NEAR(g.covered_fraction(20000, L), 0.45, 1e-15);
    EXPECT_NEAR(g.particles_at(0.45, L), 20000, 1e-9);
  }
  EXPECT_EQ(Geometry(3).covered_fraction(8e6, 272), 8e6 * M_PI / (6.0 * 272.0 * 272.0 * 272.0));
}

TEST(Geometry, MassesAreDiametersToTheDAndAddWhenAggregatesMerge) {
  for (const Geometry g : kAll) {
    SCOPED_TRACE(g.d());
    EXPECT_EQ(g.mass_of_diameter(1), 1.0);
    EXPECT_DOUBLE_EQ(g.diameter_of_mass(g.mass_of_diameter(1.7)), 1.7);
    const double merged = g.merged_diameter(1.3, 2.1);
    EXPECT_DOUBLE_EQ(g.mass_of_diameter(merged), g.mass_of_diameter(1.3) + g.mass_of_diameter(2.1));
  }
  EXPECT_EQ(Geometry(1).merged_diameter(1.25, 2.5), 3.75);  // lengths add exactly
}

// E = (d/2) N T: the energy per particle per unit temperature.
TEST(Geometry, KineticEnergyPerTemperatureIsHalfTheDimension) {
  EXPECT_EQ(Geometry(1).energy_per_temperature(), 0.5);
  EXPECT_EQ(Geometry(2).energy_per_temperature(), 1.0);
  EXPECT_EQ(Geometry(3).energy_per_temperature(), 1.5);
}

// The contact values at phi = 0 are 1 (an ideal gas); at phi = 0.208
// Carnahan–Starling's (1 - phi/2)/(1 - phi)^3, Henderson's and Tonks'.
// At the temperature unit_time_temperature the Enskog rate is 1: the time unit.
TEST(Geometry, ContactValuesAndTheEnskogTimeUnit) {
  for (const Geometry g : kAll) EXPECT_EQ(g.contact_value(0), 1.0);
  EXPECT_DOUBLE_EQ(Geometry(3).contact_value(0.208), 0.896 / std::pow(0.792, 3));
  EXPECT_DOUBLE_EQ(Geometry(2).contact_value(0.4), (1 - 0.175) / (0.6 * 0.6));
  EXPECT_DOUBLE_EQ(Geometry(1).contact_value(0.2), 1.25);
  for (const Geometry g : kAll) {
    SCOPED_TRACE(g.d());
    const double n = 0.3, phi = g.covered_fraction(n, 1.0);
    EXPECT_NEAR(g.enskog_rate(n, phi, g.unit_time_temperature(n, phi)), 1.0, 1e-14);
  }
}

// The largest grid side s with s^d cells indexable by 32 bits, exactly.
TEST(Geometry, TheGridLimitIsTheLargestSideWith32BitCells) {
  const std::int64_t sides[] = {2147483647, 46340, 1290};
  for (const Geometry g : kAll) {
    SCOPED_TRACE(g.d());
    const std::int64_t s = g.max_grid_side();
    EXPECT_EQ(s, sides[g.d() - 1]);
    EXPECT_LE(g.grid_cells(double(s)), 2147483647.0);
    EXPECT_GT(g.grid_cells(double(s + 1)), 2147483647.0);
    EXPECT_EQ(g.grid_limit(), "L < " + std::to_string(s + 1));
  }
}

TEST(Geometry, DispatchGivesTheCompileTimeDimension) {
  for (const Geometry g : kAll) EXPECT_EQ(g.dispatch([]<int D>() { return D; }), g.d());
}

}  // namespace
}  // namespace coolgas
