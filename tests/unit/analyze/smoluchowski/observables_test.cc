// What the tables report: moments, the largest cluster of a volume V, and the
// log-binned N(m) (data-schema/tsv-tables.md, "Shared table shapes").
#include <gtest/gtest.h>

#include <cmath>

#include "analyze/smoluchowski/geometric.h"
#include "analyze/smoluchowski/initial.h"
#include "analyze/smoluchowski/observables.h"
#include "common/error.h"

namespace coolgas::smoluchowski {
namespace {

TEST(SmoluchowskiObservables, LargestMassIsWhereOneClusterRemainsAbove) {
  const MassGrid g = uniform_grid(10);
  std::vector<double> c(10, 0.0);
  c[0] = 1;       // mass 1
  c[4] = 2e-3;    // mass 5: two clusters in V = 1000
  c[8] = 0.5e-3;  // mass 9: half a cluster in V = 1000
  EXPECT_EQ(largest_mass(g, c, 1000), 5);  // V(c_9) = 0.5 < 1, V(c_9 + c_5) >= 1
  EXPECT_EQ(largest_mass(g, c, 2000), 9);
  EXPECT_EQ(largest_mass(g, c, 0.5), 0);   // not even one cluster in the volume
}

TEST(SmoluchowskiObservables, BinsConserveNumberAndMassOfAGeometricGrid) {
  // Each cell's clusters are spread over its interval: binned Σ N dm equals M0,
  // and on a uniform grid the bins hold exactly Σ c over their masses.
  const MassGrid g = geometric_grid(5000, 1.3);
  std::vector<double> c(g.size());
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = std::exp(-g.mass[i] / 300);
  double binned = 0;
  for (const auto& b : binned_distribution(g, c, 10)) binned += b.N * b.dm;
  EXPECT_NEAR(binned, moments(g, c).M0, 1e-12 * binned);

  const MassGrid u = uniform_grid(30);
  std::vector<double> cu(30);
  for (int i = 0; i < 30; ++i) cu[i] = i + 1;
  const auto bins = binned_distribution(u, cu, 10);
  // Masses 13..15 form one bin of width 3 at ten bins per decade (LogBins edges 13, 16).
  bool found = false;
  for (const auto& b : bins)
    if (b.dm == 3 && std::abs(b.m - std::sqrt(13.0 * 15)) < 1e-12) {
      EXPECT_DOUBLE_EQ(b.N, (13 + 14 + 15) / 3.0);
      found = true;
    }
  EXPECT_TRUE(found);
}

TEST(SmoluchowskiObservables, InitialMassesSharedBetweenPivotsConserveNumberAndMass) {
  const MassGrid g = geometric_grid(1000, 1.5);
  std::vector<double> by_mass(700, 0.0);
  by_mass[1] = 1;
  by_mass[613] = 0.25;  // lies between two pivots of this grid
  const auto c = on_grid(g, by_mass);
  const auto m = moments(g, c);
  EXPECT_NEAR(m.M0, 1.25, 1e-14);
  EXPECT_NEAR(m.M1, 1 + 0.25 * 613, 1e-12);
  EXPECT_THROW(on_grid(uniform_grid(100), by_mass), InputError);
}

}  // namespace
}  // namespace coolgas::smoluchowski
