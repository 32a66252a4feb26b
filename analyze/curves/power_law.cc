#include "analyze/curves/power_law.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_fit.h>

#include <cmath>
#include <vector>

#include "common/error.h"
#include "common/tsv.h"

namespace coolgas {

PowerLawFit fit_power_law(const FitData& data) {
  const std::size_t n = data.t.size();
  if (n < 3) throw InputError("a power-law fit needs at least 3 points, got " + std::to_string(n));
  std::vector<double> x(n), y(n), w;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(data.t[i] > 0) || !(data.E[i] > 0))
      throw InputError("power-law fit: point t = " + format_number(data.t[i]) + ", E = " + format_number(data.E[i]) +
                       " is not in the log-log plane (both must be > 0; move the window past t = 0)");
    x[i] = std::log(data.t[i]);
    y[i] = std::log(data.E[i]);
    if (!data.err.empty()) w.push_back(std::pow(data.E[i] / data.err[i], 2));  // sigma(ln E) = err/E
  }
  gsl_set_error_handler_off();
  double c0 = 0, c1 = 0, cov00 = 0, cov01 = 0, cov11 = 0, ss = 0;
  PowerLawFit f;
  f.points = n;
  f.weighted = !w.empty();
  if (f.weighted) {
    gsl_fit_wlinear(x.data(), 1, w.data(), 1, y.data(), 1, n, &c0, &c1, &cov00, &cov01, &cov11, &ss);
  } else {
    gsl_fit_linear(x.data(), 1, y.data(), 1, n, &c0, &c1, &cov00, &cov01, &cov11, &ss);
  }
  if (!std::isfinite(c1) || !std::isfinite(cov11))
    throw InputError("power-law fit is degenerate: the " + std::to_string(n) + " points do not span a range of t");
  f.chi2_dof = ss / double(n - 2);
  f.theta = -c1;
  f.theta_err = std::sqrt(cov11);
  f.A = std::exp(c0);
  f.A_err = f.A * std::sqrt(cov00);
  return f;
}

}  // namespace coolgas
