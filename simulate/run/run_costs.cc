#include "simulate/run/run_costs.h"

#include <cmath>

#include "simulate/scene/scene.h"

namespace coolgas {

namespace {

// The gas: 3.497e7 collisions in 52.9 CPU-s (L = 68, N = 1.3e5, to t = 1e4)
// and 7.815e7 in 192.0 (L = 136, N = 1e6, to t = 1e3); larger grids miss
// the cache more often.
constexpr double kCollisionsPerSecondSmall = 6.61e5, kCollisionsPerSecondLarge = 4.07e5;
constexpr double kSmallRunParticles = 1.3e5;
// Disks and rods collide faster per CPU second than spheres, by d: small
// runs (the gas at N = 2e4 to t = 1000, in turns: rods x2.77 and disks x3.04
// the spheres' rate, tests/bench/dimension_rates.sh); large ones W5D1 x1.74
// and W5D2 x1.29 the collisions per CPU second of W5, 10^6 particles
// (tests/bench/README.md).
constexpr double kSmallRunFactor[4] = {0, 2.77, 3.04, 1.0}, kLargeRunFactor[4] = {0, 1.74, 1.29, 1.0};

// Aggregation at N = 8e6 to t = 1e5 (the aggregation_bench): merges per
// second and the set-up (a dilute start places and equilibrates slower),
// interpolated in ln phi between the two densities measured.
constexpr double kDensePhi = 0.208, kDilutePhi = 0.005;
constexpr double kMergesPerSecondDense = 35971, kMergesPerSecondDilute = 12813;
constexpr double kSetupSecondsDense = 153.2, kSetupSecondsDilute = 688.5, kSetupParticles = 8e6;
constexpr double kAggregationBytesPerParticle = 187;  // peak at N = 1e6 (the gas: kBytesPerParticle)

// A dump's compressed size per particle: the gas's largest measured (late,
// clustered: 47 at L = 34, t = 1e5); aggregation adds id, mass and diameter,
// counted at the gas's compression (47 + 20 x 42/61).
constexpr double kDumpBytesGas = 47, kDumpBytesAggregation = 62;

// The driven gas's kicks (simulate/engine/driving.h), each a rebuild of the
// engine, cost as much as kKickCostPerPeriod / driving.period collisions per
// collision: CPU seconds of a driven gas of 2e4 spheres (phi = 0.1, r0 = 0.8,
// power 0.05, to t = 100) at periods 0.1, 0.5, 2 and 8 were 9.42, 3.26, 2.24
// and 1.88, about 1.76 (1 + 0.55 / period).
constexpr double kKickCostPerPeriod = 0.55;

// A rough collision costs 1.06 smooth ones (W1R against W1), a mixture's
// 1/0.77 (W1M against W1: larger cells, a species per candidate); both rows
// of tests/bench/README.md's current figures.
constexpr double kRoughCollisionCost = 1.06, kMixtureCollisionCost = 1 / 0.77;

double gas_cpu_seconds(const Scene& s, double collisions) {
  const int d = s.geometry().d();
  double rate = double(s.N) <= kSmallRunParticles ? kCollisionsPerSecondSmall * kSmallRunFactor[d]
                                                   : kCollisionsPerSecondLarge * kLargeRunFactor[d];
  if (s.rough()) rate /= kRoughCollisionCost;
  if (s.mixture()) rate /= kMixtureCollisionCost;
  const double kicks = s.driving_power ? collisions * kKickCostPerPeriod / s.driving_period : 0;
  return (collisions + kicks + s.equilibrate * double(s.N) / 2) / rate;
}

double aggregation_cpu_seconds(const Scene& s, double merges) {
  const double f = std::log(s.phi / kDilutePhi) / std::log(kDensePhi / kDilutePhi);
  const double rate = std::exp(std::log(kMergesPerSecondDilute) + f * std::log(kMergesPerSecondDense / kMergesPerSecondDilute));
  const double setup = std::exp(std::log(kSetupSecondsDilute) + f * std::log(kSetupSecondsDense / kSetupSecondsDilute));
  return merges / rate + double(s.N) / kSetupParticles * setup;
}

}  // namespace

const ModelCosts kGasCosts{kBytesPerParticle, kDumpBytesGas, gas_cpu_seconds};
const ModelCosts kAggregationCosts{kAggregationBytesPerParticle, kDumpBytesAggregation, aggregation_cpu_seconds};

}  // namespace coolgas
