// The (theta, z) that collapse E(t) curves of several L best: minimum of the
// collapse quality (quality.h) by the Nelder-Mead simplex (GSL
// nmsimplex2), with uncertainties from a bootstrap: every replica is
// minimised again and the errors are the standard deviations of the replicas.
// Replicas (GSL mt19937, fixed seed):
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

namespace coolgas {

struct CollapseSearch {
  double theta0 = 1.2, z0 = 2.5;  // starting point (the paper's values)
  double min_overlap_decades = 0.5;
  int bootstrap = 100;  // replicas; 0: no uncertainties
  std::uint64_t seed = 1;
};

enum class BootstrapKind { kErrors, kRows };

struct CollapseFit {
  double theta = 0, z = 0, quality = 0;
  double theta_err = 0, z_err = 0;  // 0 when bootstrap = 0
  int replicas = 0;
  BootstrapKind kind = BootstrapKind::kErrors;
};

// Needs >= 2 curves. InputError if the curves never overlap (every pair
// penalised at the optimum: no collapse was found).
CollapseFit optimize_collapse(const std::vector<ScalingCurve>& curves, const CollapseSearch& search);

}  // namespace coolgas
