// The contact value of the radial distribution function of equilibrium hard
// spheres and disks, run by the engine (elastic model) and measured by
// coolgas-structure's g(r) (analyze/structure/radial_distribution.h): within
// 1 % of Carnahan–Starling's (1 − φ/2)/(1 − φ)³ at φ = 0.1, 0.2 and 0.3,
// and of Henderson's (1 − 7φ/16)/(1 − φ)² for disks at φ = 0.2 and 0.4
// (tests/physics/README.md: both are accurate to well under 0.5 % there).
// The pairs of 800 frames a quarter of a collision time apart are pooled
// before the fit; the fit's own error is asked to be below 0.35 %, so the
// 1 % is a check the statistics can fail.
#include <gtest/gtest.h>

#include "analyze/structure/radial_distribution.h"
#include "simulate/run/engine_factory.h"
#include "simulate/start/initial_state.h"
#include "tests/support/density_cases.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

using test::Density;

class ContactValue : public ::testing::TestWithParam<Density> {};

TEST_P(ContactValue, IsTheEquilibriumOne) {
  const Density d = GetParam();
  const Scene s = test::in_dimension(test::elastic_scene(4000, d.phi, d.seed), d.dimension);
  const Geometry g(d.dimension);
  auto e = make_engine(s, initial_state(s), 0.0);  // relaxed for system.equilibrate collision times
  PairDistances pairs(g, 1.2, 50);
  std::vector<double> p(3 * std::size_t(s.N));
  for (int frame = 1; frame <= 800; ++frame) {
    e->run_until(0.25 * frame, std::int64_t(1) << 40, nullptr);
    const EngineFrame f = e->frame();
    for (std::size_t i = 0; i < f.position.size(); ++i)
      for (int k = 0; k < 3; ++k) p[3 * i + k] = f.position[i][k];
    pairs.add(s.L, p);
  }
  const coolgas::ContactValue c = pairs.contact(5);
  const double expected = g.contact_value(d.phi);
  EXPECT_NEAR(c.g / expected, 1, 0.01) << "g(sigma+) = " << c.g << " +- " << c.err << ", expected " << expected;
  EXPECT_LT(c.err / expected, 0.0035);
}

INSTANTIATE_TEST_SUITE_P(HardSpheresAndDisks, ContactValue,
                         ::testing::Values(Density{3, 0.1, 23}, Density{3, 0.2, 23}, Density{3, 0.3, 23},
                                           Density{2, 0.2, 43}, Density{2, 0.4, 43}),
                         test::density_case_name);

}  // namespace
}  // namespace coolgas
