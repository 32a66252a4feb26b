// The (theta, z) that collapse E(t) curves of several L best: minimum of the
// collapse quality (quality.h) by the Nelder-Mead simplex (GSL
// nmsimplex2), with uncertainties from resampling: every replica is
// minimised again. Replicas, in order of preference:
//  - kRuns, when every size has two or more runs (one table per seed): the
//    stratified delete-one jackknife over whole runs (Efron & Stein 1981;
//    the resampling finite-size-scaling studies use): replica (s, r) drops
//    run r of size s, and var = sum_s (n_s - 1)/n_s sum_r (theta_(s,r) -
//    mean_r theta_(s,.))^2. It keeps each run's correlations in time, so
//    the error falls as 1/sqrt(runs) and covers the truth at its stated
//    rate (tests/unit/analyze/collapse/resampling_test.cc). Deterministic.
// Otherwise a bootstrap (GSL mt19937, fixed seed), the errors being the
// standard deviations of the replicas:
//  - kErrors, when every curve has errors (the E_err of an ensemble over
//    seeds): ln E_i + (E_err_i/E_i) xi_i with xi_i ~ N(0, 1), a parametric
//    bootstrap standing in for one over seeds. It treats the errors of
//    different rows as independent; those of an ensemble mean at neighbouring
//    times are correlated, which it does not capture.
//  - kRows, otherwise: each curve's rows drawn with replacement, duplicates
//    dropped. Interpolation between the rows kept hides part of the noise, so
//    this underestimates the errors (by about 2x on the synthetic test curves).
#pragma once
#include <cstdint>
#include <vector>

#include "analyze/collapse/curves.h"
#include "analyze/collapse/ensemble.h"

namespace coolgas {

struct CollapseSearch {
  double theta0 = 1.2, z0 = 2.5;  // starting point (the paper's values)
  double min_overlap_decades = 0.5;
  int bootstrap = 100;  // bootstrap replicas (kErrors, kRows); 0: no uncertainties
  std::uint64_t seed = 1;
};

enum class BootstrapKind { kRuns, kErrors, kRows };

struct CollapseFit {
  double theta = 0, z = 0, quality = 0;
  double theta_err = 0, z_err = 0;  // 0 when bootstrap = 0
  int replicas = 0;
  BootstrapKind kind = BootstrapKind::kErrors;
  // The error of the product z theta (the paper's E L^(z theta): mean field
  // has z theta = d) from the same replicas: theta and z are correlated,
  // so it is not theirs combined as if independent. 0 when bootstrap = 0,
  // and when the product is held fixed (fixed_product.h).
  double z_theta_err = 0;
};

// Needs >= 2 sizes; the collapse is of each size's mean curve. InputError if
// the curves never overlap (every pair penalised at the optimum: no collapse
// was found). bootstrap = 0 turns every kind of uncertainty off.
CollapseFit optimize_collapse(const std::vector<SizeEnsemble>& sizes, const CollapseSearch& search);
// The same with one curve per size (an ensemble mean or a single run).
CollapseFit optimize_collapse(const std::vector<ScalingCurve>& curves, const CollapseSearch& search);

}  // namespace coolgas
