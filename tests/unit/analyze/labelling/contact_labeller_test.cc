// The contact labeller against a slow exact reference: a breadth-first
// search over every pair of particles, bonded when their minimum-image
// distance is below the cutoff (nothing shared with the labeller: no cell
// list, no union-find). Same partition of the particles in d = 1, 2, 3, on
// random frames dense enough for clusters of every size, and a chain of
// contacts across the periodic boundary is one cluster.
#include "analyze/labelling/contact_labeller.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>

#include "common/random.h"

namespace coolgas {
namespace {

// The component of each particle, numbered in the order of their smallest
// particles; bonded closer than cutoff times their contact distance, the mean
// of their diameters (none given: 1).
std::vector<int> all_pairs_components(const std::vector<double>& p, double L, double cutoff,
                                      const std::vector<double>& diameter = {}) {
  const std::size_t n = p.size() / 3;
  auto bonded = [&](std::size_t i, std::size_t j) {
    double r2 = 0;
    for (int k = 0; k < 3; ++k) {
      const double dx = std::remainder(p[3 * i + k] - p[3 * j + k], L);  // the minimum image
      r2 += dx * dx;
    }
    const double bond = diameter.empty() ? cutoff : cutoff * (diameter[i] + diameter[j]) / 2;
    return r2 < bond * bond;
  };
  std::vector<int> component(n, -1);
  int next = 0;
  for (std::size_t s = 0; s < n; ++s) {
    if (component[s] >= 0) continue;
    std::queue<std::size_t> q;
    q.push(s);
    component[s] = next;
    while (!q.empty()) {
      const std::size_t i = q.front();
      q.pop();
      for (std::size_t j = 0; j < n; ++j)
        if (component[j] < 0 && bonded(i, j)) component[j] = next, q.push(j);
    }
    ++next;
  }
  return component;
}

// n points uniform in [0, L)^d, the coordinates past d 0.
std::vector<double> uniform_points(std::size_t n, double L, Geometry g, Random& rng) {
  std::vector<double> p(3 * n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < g.d(); ++k) p[3 * i + k] = L * rng.uniform();
  return p;
}

class EveryDimension : public ::testing::TestWithParam<int> {};

// The labeller's clusters against the reference's components: the roots map
// one to one onto them, in the same order, and the masses agree. Returns the
// largest cluster's mass.
std::int64_t expect_reference_partition(const ContactLabeller& labeller, const std::vector<int>& reference) {
  const std::size_t n = reference.size();
  std::map<std::int32_t, int> root_to_component;
  std::vector<std::int64_t> masses(std::size_t(*std::max_element(reference.begin(), reference.end()) + 1), 0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto [it, fresh] = root_to_component.emplace(labeller.root_of(i), reference[i]);
    EXPECT_EQ(it->second, reference[i]) << "particle " << i;
    ++masses[std::size_t(reference[i])];
  }
  EXPECT_EQ(labeller.clusters(), masses.size());
  std::size_t k = 0;
  std::int64_t largest = 0;
  labeller.for_each_mass([&](std::int64_t m) {
    // in the order of the smallest particles, as the reference numbers them
    if (k < masses.size()) {
      EXPECT_EQ(m, masses[k]);
    }
    ++k;
    largest = std::max(largest, m);
  });
  return largest;
}

// Ideal-gas points at a density where the bonds make clusters from single
// particles to a large one (cutoff 1.1; mean bonds per particle about 1.5):
// the labeller's roots map one to one onto the reference's components, in
// the same order, and the masses agree.
TEST_P(EveryDimension, LabelsEqualAnAllPairsLabelling) {
  const Geometry g(GetParam());
  Random rng(101 + GetParam());
  const double cutoff = 1.1;
  const double L = g.d() == 1 ? 600 : (g.d() == 2 ? 30 : 10);
  const std::size_t n = g.d() == 1 ? 400 : (g.d() == 2 ? 350 : 300);
  ContactLabeller labeller;
  for (int frame = 0; frame < 5; ++frame) {
    const auto p = uniform_points(n, L, g, rng);
    labeller.label(L, p, cutoff, g);
    const auto reference = all_pairs_components(p, L, cutoff);
    const std::int64_t largest = expect_reference_partition(labeller, reference);
    EXPECT_GT(largest, 5) << "frame " << frame;  // the frames have clusters, not just pairs
    EXPECT_LT(largest, std::int64_t(n)) << "frame " << frame;
  }
}

// A mixture's points, each of diameter 0.6 or 1.8 at random (3 : 1), so
// pairs bond within 1.1 x 0.6, 1.32 or 1.98: the same partition as the
// reference's, and one the unit bond (1.1 for every pair) does not give.
TEST_P(EveryDimension, AMixturesLabelsEqualAnAllPairsLabellingByContactDistances) {
  const Geometry g(GetParam());
  Random rng(211 + GetParam());
  const double cutoff = 1.1;
  const double L = g.d() == 1 ? 600 : (g.d() == 2 ? 30 : 10);
  const std::size_t n = g.d() == 1 ? 300 : (g.d() == 2 ? 250 : 220);
  ContactLabeller labeller;
  for (int frame = 0; frame < 5; ++frame) {
    const auto p = uniform_points(n, L, g, rng);
    std::vector<double> diameter(n);
    for (double& s : diameter) s = rng.uniform() < 0.75 ? 0.6 : 1.8;
    labeller.label(L, p, cutoff, g, diameter);
    const auto reference = all_pairs_components(p, L, cutoff, diameter);
    const std::int64_t largest = expect_reference_partition(labeller, reference);
    EXPECT_GT(largest, 5) << "frame " << frame;
    EXPECT_LT(largest, std::int64_t(n)) << "frame " << frame;
    EXPECT_NE(reference, all_pairs_components(p, L, cutoff)) << "frame " << frame;  // the diameters matter
  }
}

INSTANTIATE_TEST_SUITE_P(D, EveryDimension, ::testing::Values(1, 2, 3));

// A chain of particles 1.05 apart along x through the periodic boundary,
// and one 1.2 beyond its end: the chain is one cluster, the last alone.
TEST(ContactLabeller, ChainsJoinAcrossThePeriodicBoundary) {
  const double L = 20;
  std::vector<double> p;
  for (int i = 0; i < 6; ++i) p.insert(p.end(), {std::fmod(17.0 + 1.05 * i, L), 3.0, 4.0});
  p.insert(p.end(), {std::fmod(17.0 + 1.05 * 5 + 1.2, L), 3.0, 4.0});
  ContactLabeller labeller;
  labeller.label(L, p, 1.1, Geometry(3));
  std::vector<std::int64_t> masses;
  labeller.for_each_mass([&](std::int64_t m) { masses.push_back(m); });
  EXPECT_EQ(masses, (std::vector<std::int64_t>{6, 1}));
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(labeller.root_of(i), 0);
  EXPECT_EQ(labeller.root_of(6), 6);
}

}  // namespace
}  // namespace coolgas
