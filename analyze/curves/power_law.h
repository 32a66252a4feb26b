// Power law E = A t^-theta fitted by (weighted) least squares of ln E against ln t.
#pragma once
#include <cstddef>

#include "analyze/curves/fit_data.h"

namespace coolgas {

struct PowerLawFit {
  double theta = 0, theta_err = 0;
  double A = 0, A_err = 0;
  // Weighted: chi^2/(n-2) with sigma(ln E) = err/E. Unweighted: the residual
  // variance of ln E, which also sets the standard errors.
  double chi2_dof = 0;
  std::size_t points = 0;
  bool weighted = false;
};

// Needs >= 3 samples, all with t > 0 and E > 0 (InputError otherwise).
// Weighted standard errors take the given errors as independent; errors of an
// ensemble mean at neighbouring times are correlated, so they are a lower bound.
PowerLawFit fit_power_law(const FitData& data);

}  // namespace coolgas
