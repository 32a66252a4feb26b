// E(t) curves of several system sizes L, kept in log space, and the
// finite-size scaling of the paper's Eq. (2): E(t) = L^{-z theta} f(t / L^z),
// so that x = t / L^z and y = E L^{z theta} fall on one curve f(x).
#pragma once
#include <string>
#include <vector>

#include "analyze/curves/fit_data.h"
#include "common/tsv.h"

namespace coolgas {

struct ScalingCurve {
  std::string source;
  double L = 0, ln_L = 0;
  std::vector<double> t, E;          // the rows used (t > 0), t increasing
  std::vector<double> ln_t, ln_E;
  std::vector<double> ln_E_err;      // standard error of ln E (E_err/E); empty if the table has none
  std::vector<double> ln_E_var;      // variance of ln E that weighs the collapse (seed_weights.h); empty: unweighted
  // Scaled coordinates: ln x = ln t - z ln L, ln y = ln E + z theta ln L.
  double ln_x_shift(double z) const { return -z * ln_L; }
  double ln_y_shift(double theta, double z) const { return z * theta * ln_L; }
};

// The rows of an E(t) table with t in `t_window` and t > 0; L from the
// provenance line "# L: ..." (coolgas-energy writes it); errors from the error
// column chosen as in coolgas-fit (error_column in analyze/curves/fit_data.h). InputError if L is
// missing or not > 0, if E <= 0, if t does not increase, or fewer than 2 rows remain.
ScalingCurve make_scaling_curve(const Table& table, const FitColumns& columns, const Window& t_window);

// ys at x, linear between the points (xs increasing), clamped to the end
// values outside them: a curve's ln E or its variance at any ln t.
double interpolate_clamped(const std::vector<double>& xs, const std::vector<double>& ys, double x);

// The same curve with only the rows at `rows` (sorted, unique indices): bootstrap replicas.
ScalingCurve subset(const ScalingCurve& c, const std::vector<std::size_t>& rows);

}  // namespace coolgas
