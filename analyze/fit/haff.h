// Haff's law E(t) = E0 / (1 + t/t0)^2 fitted by nonlinear least squares
// (GSL trust-region Levenberg-Marquardt) on ln E, so that every decade of E
// counts alike; with errors, the residuals are weighted by sigma(ln E) = err/E.
// Reference: Haff, J. Fluid Mech. 134, 401 (1983); t0 = 6/(1 - r^2) in this
// project's units (see the README).
#pragma once
#include <cstddef>

#include "analyze/curves/fit_data.h"

namespace coolgas {

struct HaffFit {
  double E0 = 0, E0_err = 0;
  double t0 = 0, t0_err = 0;
  // Weighted: chi^2/(n-2); unweighted: residual variance of ln E (which then scales the errors).
  double chi2_dof = 0;
  std::size_t points = 0;
  bool weighted = false;
};

// Needs >= 3 samples with t >= 0 and E > 0. InputError if the fit does not converge.
HaffFit fit_haff(const FitData& data);

}  // namespace coolgas
