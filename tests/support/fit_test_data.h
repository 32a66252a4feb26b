// Synthetic E(t) samples with multiplicative Gaussian noise for the fit
// tests: E_i = model(t_i) exp(sigma xi_i), xi_i ~ N(0, 1) from GSL's mt19937
// with a fixed seed, and err_i = sigma E_i so that sigma(ln E) = sigma.
#pragma once
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include <cmath>
#include <functional>

#include "analyze/curves/fit_data.h"

namespace coolgas::test {

inline FitData noisy_samples(const std::function<double(double)>& model, double t_lo, double t_hi, int per_decade,
                             double sigma, unsigned long seed) {
  gsl_rng* rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, seed);
  FitData d;
  const int n = static_cast<int>(std::lround(std::log10(t_hi / t_lo) * per_decade));
  for (int k = 0; k <= n; ++k) {
    const double t = t_lo * std::pow(10.0, double(k) / per_decade);
    const double E = model(t) * std::exp(sigma * gsl_ran_gaussian(rng, 1.0));
    d.t.push_back(t);
    d.E.push_back(E);
    if (sigma > 0) d.err.push_back(sigma * E);
  }
  gsl_rng_free(rng);
  return d;
}

}  // namespace coolgas::test
