// Hard disks (system.dimension = 2) against kinetic theory and conservation
// laws (tests/physics/README.md; their time unit, Enskog's omega with
// Henderson's contact value, is checked with the spheres' in
// collision_rate_test.cc):
//   - Haff's law in 2D: dT/dt = -(1 - r^2) omega T / d with d = 2, so
//     T(t) = T0 / (1 + t/t0)^2 with t0 = 4 / (1 - r^2) in units of 1/omega0;
//   - the temperature is per component, T = m <v_x^2>: the energy per disk is
//     T (d/2 = 1), not the 3/2 T of a sphere;
//   - momentum kept to round-off, no overlap, and disks never leave z = 0.
#include <gtest/gtest.h>

#include <cmath>

#include "simulate/run/engine_factory.h"
#include "simulate/start/initial_state.h"
#include "tests/support/kinetic_theory.h"
#include "tests/support/min_distance.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

// As in 3D (haff_law_test.cc), with 2D's t0 = 4 / (1 - r^2).
TEST(DiskHaffLaw, TemperatureAndCollisionRateFollowTheHomogeneousCooling) {
  const double r = 0.98;
  test::expect_haff_cooling(test::inelastic_disk_scene(4000, 0.05, r, 0.0, 42), 4.0 / (1.0 - r * r));  // t0 about 101
}

// <v_x^2> and <v_y^2> over the disks (unit masses).
std::pair<double, double> mean_squares(const EngineFrame& f) {
  double x = 0, y = 0;
  for (const Vec3& v : f.velocity) x += v.x * v.x, y += v.y * v.y;
  return {x / double(f.velocity.size()), y / double(f.velocity.size())};
}

TEST(DiskTemperature, IsPerComponentAndTheEnergyPerDiskIsT) {
  const Scene s = test::disk_scene(20000, 0.2, 43);
  const double T0 = initial_temperature(s);
  auto e = make_engine(s, initial_state(s), 0.0);
  // E = (d/2) T with d = 2: exactly T0 (draw_velocities scales to it).
  EXPECT_NEAR(e->observables().kinetic_energy / T0, 1.0, 1e-12);
  const auto [x, y] = mean_squares(e->frame());
  EXPECT_NEAR(x / T0, 1.0, 0.03);  // statistics of 20000 disks: 1 %
  EXPECT_NEAR(y / T0, 1.0, 0.03);
  EXPECT_NEAR((x + y) / (2 * T0), 1.0, 1e-12);
  e->run_until(5.0, std::int64_t(1) << 40, nullptr);  // elastic: equipartition holds, the energy stays
  const auto [x5, y5] = mean_squares(e->frame());
  EXPECT_NEAR(x5 / T0, 1.0, 0.03);
  EXPECT_NEAR(y5 / T0, 1.0, 0.03);
  // The same sum in 3D would be 3/2 T: the factor a 2D run must not inherit.
  const Scene spheres = test::elastic_scene(4000, 0.2, 43);
  EXPECT_NEAR(make_engine(spheres, initial_state(spheres), 0.0)->observables().kinetic_energy /
                  initial_temperature(spheres),
              1.5, 1e-12);
}

TEST(DiskConservation, MomentumToRoundOffNoOverlapAndTheDisksStayInThePlane) {
  // A clustering 2D gas (r0 = 0.1, delta = 1e-4, as the paper's in 3D).
  const Scene s = test::inelastic_disk_scene(8000, 0.3, 0.1, 1e-4, 44);
  auto e = make_engine(s, initial_state(s), 0.0);
  double speeds = 0;
  for (const Vec3& v : e->frame().velocity) speeds += std::sqrt(dot(v, v));
  const double e0 = e->observables().kinetic_energy;
  while (e->counters().collisions < 500000) e->run_until(e->now() * 1.2 + 1.0, 1 << 30, nullptr);
  const Vec3 p = e->observables().momentum;
  EXPECT_LT(std::sqrt(dot(p, p)), 1e-12 * speeds);
  EXPECT_EQ(p.z, 0.0);
  EXPECT_LT(e->observables().kinetic_energy, 0.1 * e0);  // it did cool
  const EngineFrame f = e->frame();
  for (std::size_t i = 0; i < f.position.size(); ++i) {
    ASSERT_EQ(f.position[i].z, 0.0) << i;
    ASSERT_EQ(f.velocity[i].z, 0.0) << i;
    ASSERT_EQ(f.image[i][2], 0) << i;
  }
  EXPECT_LT(test::largest_overlap(f.position, e->box()), 1e-9);
}

}  // namespace
}  // namespace coolgas
