// The mass-radius relation M ~ R_g^{d_f} over clusters of known dimension:
// rods (1), slabs (2) and balls (3) of unit cells, and the clusters of random
// site percolation at its threshold on the simple cubic lattice, whose
// fractal dimension is D = 2.5226 (Ballesteros et al., J. Phys. A 32, 1
// (1999)); threshold p_c = 0.3116077 (Wang et al., PRE 87, 052107 (2013)).
#include "analyze/shape/mass_radius.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>

#include "common/random.h"
#include "tests/unit/analyze/shape/percolation.h"

namespace coolgas {
namespace {

// Shapes of objects of growing size, each alone in an integer box of side L
// with one particle at each of its cells' centres.
std::vector<ClusterShape> shapes_of(int L, int count, const std::function<std::vector<std::array<int, 3>>(int)>& object) {
  std::vector<ClusterShape> out;
  ClusterShapes shapes;
  for (int size = 1; size <= count; ++size) {
    std::vector<double> p;
    for (const auto& c : object(size))
      for (int a : c) p.push_back(a + 0.5);
    for (const ClusterShape& s : shapes.of_particles(ClusterGrid(L, Geometry(3)), p)) out.push_back(s);
  }
  return out;
}

MassRadius fit(const std::vector<ClusterShape>& s, const std::string& window) {
  return mass_radius(s, 10, parse_window(window, "--fit-mass"));
}

TEST(MassRadius, RodsAreOneDimensional) {
  const auto s = shapes_of(64, 60, [](int n) {
    std::vector<std::array<int, 3>> c;
    for (int i = 0; i < n; ++i) c.push_back({2 + i, 3, 3});
    return c;
  });
  const MassRadius mr = fit(s, "10:");
  EXPECT_NEAR(mr.d_f, 1, 0.02);
  EXPECT_GE(mr.fit_bins, 6);
  EXPECT_NEAR(mr.asphericity, 1, 1e-9);
}

TEST(MassRadius, SlabsAreTwoDimensional) {
  const auto s = shapes_of(40, 30, [](int n) {
    std::vector<std::array<int, 3>> c;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) c.push_back({2 + i, 3, 2 + j});
    return c;
  });
  EXPECT_NEAR(fit(s, "10:").d_f, 2, 0.03);
}

TEST(MassRadius, BallsAreThreeDimensional) {
  const auto s = shapes_of(40, 15, [](int R) {
    std::vector<std::array<int, 3>> c;
    for (int i = -R; i <= R; ++i)
      for (int j = -R; j <= R; ++j)
        for (int k = -R; k <= R; ++k)
          if (i * i + j * j + k * k <= R * R) c.push_back({20 + i, 20 + j, 20 + k});
    return c;
  });
  EXPECT_NEAR(fit(s, "30:").d_f, 3, 0.05);
}

// Sites of a 128^3 periodic lattice occupied with probability p_c, one
// particle at each occupied site's centre: the finite clusters obey
// M ~ R_g^D with D = 2.52. Measured here: d_f = 2.50 +- 0.03 from 50 sites
// on; small clusters pull it down (2.44 from 20 on), as corrections to
// scaling do, and clusters near the box size up (2.60 from 200 on).
TEST(MassRadius, PercolationClustersAtThresholdHaveTheKnownFractalDimension) {
  const MassRadius mr = test::percolation_mass_radius(128, 3, 0.3116077, 7, "50:");
  EXPECT_NEAR(mr.d_f, 2.5226, 0.1);
  EXPECT_LT(mr.d_f_err, 0.1);
  EXPECT_GE(mr.fit_bins, 10);
}

}  // namespace
}  // namespace coolgas
