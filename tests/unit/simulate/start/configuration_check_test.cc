// A configuration from outside our own start is checked before an engine
// runs on it: sizes, box, finite values inside the box, and no overlapping
// pair (named, with its distance), the grid search agreeing with all pairs.
#include "simulate/start/configuration_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "common/error.h"
#include "common/random.h"

namespace coolgas {
namespace {

// n^3 spheres on a simple cubic lattice of spacing a (no overlaps for a >= 1).
Particles lattice(int n, double a) {
  Particles p;
  p.L = n * a;
  p.resize(std::size_t(n) * n * n);
  for (int i = 0; i < n * n * n; ++i) {
    p.r[i] = {a * (i % n + 0.5), a * (i / n % n + 0.5), a * (i / (n * n) + 0.5)};
    p.v[i] = {0.1 * (i % 7), -0.2, 0.3};
  }
  return p;
}

std::string error_of(const Particles& p, const AggregateState* a = nullptr) {
  try {
    check_configuration(p, a, "f.h5", Geometry(3));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ConfigurationCheck, ALatticeAtContactPasses) {
  EXPECT_EQ(error_of(lattice(6, 1.2)), "");
  EXPECT_EQ(error_of(lattice(5, 1.0)), "");  // every neighbour exactly at contact
  EXPECT_EQ(error_of(lattice(5, 1.0 - 1e-12)), "");  // round-off below contact is tolerated
}

TEST(ConfigurationCheck, AnOverlappingPairIsNamedWithItsDistance) {
  Particles p = lattice(6, 1.5);
  p.r[17] = {p.r[3].x + 0.3, p.r[3].y, p.r[3].z};
  EXPECT_NE(error_of(p).find("particles 3 and 17 overlap: their centres are 0.3"), std::string::npos) << error_of(p);
  // Across the periodic boundary too.
  Particles q = lattice(6, 1.5);
  q.r[0] = {0.1, 5.0, 5.0};
  q.r[1] = {q.L - 0.2, 5.0, 5.0};
  EXPECT_NE(error_of(q).find("particles 0 and 1 overlap"), std::string::npos) << error_of(q);
}

TEST(ConfigurationCheck, ValuesOutsideTheBoxOrNotFiniteAreRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  Particles p = lattice(4, 1.5);
  p.r[5].y = p.L;
  EXPECT_NE(error_of(p).find("particle 5 is at"), std::string::npos);
  EXPECT_NE(error_of(p).find("outside the box [0, 6)"), std::string::npos) << error_of(p);
  p.r[5].y = -1e-300;
  EXPECT_NE(error_of(p).find("particle 5"), std::string::npos);
  p.r[5].y = nan;
  EXPECT_NE(error_of(p).find("particle 5 is at (2.25, nan"), std::string::npos) << error_of(p);
  p.r[5].y = 1e300;
  EXPECT_NE(error_of(p).find("particle 5"), std::string::npos);
  Particles v = lattice(4, 1.5);
  v.v[2].z = 1e200;  // its square overflows
  EXPECT_NE(error_of(v).find("particle 2 has velocity"), std::string::npos);
  v.v[2].z = nan;
  EXPECT_NE(error_of(v).find("particle 2 has velocity"), std::string::npos);
  Particles box = lattice(4, 1.5);
  box.L = inf;
  EXPECT_NE(error_of(box).find("L = inf is not a finite number"), std::string::npos);
  box.L = 2;
  EXPECT_NE(error_of(box).find("too small"), std::string::npos);
  box.L = 3e9;
  EXPECT_NE(error_of(box).find("2^31 grid cells"), std::string::npos);
  Particles one = lattice(1, 1.5);
  EXPECT_NE(error_of(one).find("N = 1 particles"), std::string::npos);
}

TEST(ConfigurationCheck, AggregatesUseTheirDiametersAndSkipEmptySlots) {
  Particles p = lattice(5, 2.0);
  AggregateState a = AggregateState::unit_spheres(p.size());
  EXPECT_EQ(error_of(p, &a), "");
  a.diameter[7] = a.diameter[8] = 2.5;  // neighbours 2.0 apart, contact at 2.5
  EXPECT_NE(error_of(p, &a).find("particles 7 and 8 overlap"), std::string::npos) << error_of(p, &a);
  a.id[8] = -1;  // an empty slot is no sphere
  EXPECT_EQ(error_of(p, &a), "");
  a.diameter[7] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(error_of(p, &a).find("particle 7 has diameter nan"), std::string::npos);
}

// The grid search finds an overlap exactly when the all-pairs search does.
TEST(ConfigurationCheck, GridSearchAgreesWithAllPairs) {
  Random rng(11);
  int refused = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Particles p;
    p.L = 6 + 6 * rng.uniform();
    p.resize(2 + rng.below(30));
    for (auto& r : p.r) r = {p.L * rng.uniform(), p.L * rng.uniform(), p.L * rng.uniform()};
    bool overlap = false;
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = i + 1; j < p.size(); ++j) {
        Vec3 d{p.r[j].x - p.r[i].x, p.r[j].y - p.r[i].y, p.r[j].z - p.r[i].z};
        for (int k = 0; k < 3; ++k) d[k] -= p.L * std::round(d[k] / p.L);
        overlap |= std::sqrt(dot(d, d)) < 1 - kOverlapTolerance;
      }
    const std::string e = error_of(p);
    EXPECT_EQ(!e.empty(), overlap) << "trial " << trial << ": " << e;
    refused += !e.empty();
  }
  EXPECT_GT(refused, 30);  // both outcomes are exercised
  EXPECT_LT(refused, 270);
}

}  // namespace
}  // namespace coolgas
