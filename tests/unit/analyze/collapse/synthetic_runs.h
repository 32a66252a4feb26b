// Synthetic runs for the collapse tests: each run of size L is the paper's
// Eq. (2), E = L^{-z theta} f(t/L^z) with f(x) = x^-theta (1 + x)^(theta - eta),
// times exp(a + b u(t) + c w_i): a run-level offset a and tilt b (u runs from
// -1 to 1 over the run's six decades of t) and a small white part c, so its
// points are correlated in time as a real run's are. Fixed seeds make every
// number reproducible.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include "analyze/collapse/ensemble.h"
#include "common/random.h"

namespace coolgas::test {

inline constexpr double kRunOffset = 0.05, kRunTilt = 0.05, kRunWhite = 0.005;

inline ScalingCurve synthetic_run(double L, double theta, double z, double eta, Random& rng) {
  const double a = kRunOffset * rng.normal(), b = kRunTilt * rng.normal();
  ScalingCurve c;
  c.source = "synthetic";
  c.L = L;
  c.ln_L = std::log(L);
  const int per_decade = 10, decades = 6;  // t from 1 to 1e6
  for (int k = 0; k <= per_decade * decades; ++k) {
    const double t = std::pow(10.0, double(k) / per_decade), x = t / std::pow(L, z);
    const double u = 2.0 * k / (per_decade * decades) - 1;
    const double ln_E = -z * theta * c.ln_L - theta * std::log(x) + (theta - eta) * std::log1p(x) + a + b * u +
                        kRunWhite * rng.normal();
    c.t.push_back(t);
    c.E.push_back(std::exp(ln_E));
    c.ln_t.push_back(std::log(t));
    c.ln_E.push_back(ln_E);
  }
  return c;
}

// runs_per_size runs of each of L = 16, 32, 64.
inline std::vector<SizeEnsemble> synthetic_ensemble(double theta, double z, double eta, int runs_per_size,
                                                    std::uint64_t seed) {
  Random rng(seed);
  std::vector<SizeEnsemble> sizes;
  for (double L : {16.0, 32.0, 64.0}) {
    SizeEnsemble s{L, {}, {}};
    for (int r = 0; r < runs_per_size; ++r) s.runs.push_back(synthetic_run(L, theta, z, eta, rng));
    sizes.push_back(s);
  }
  return sizes;
}

}  // namespace coolgas::test
