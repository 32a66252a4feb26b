#include "analyze/fit/local_slope.h"

#include <gsl/gsl_fit.h>

#include <cmath>

#include "common/error.h"
#include "common/interrupt.h"
#include "common/tsv.h"

namespace coolgas {

std::vector<SlopePoint> local_slope(const FitData& data, double half_width_decades) {
  if (!(half_width_decades > 0))
    throw InputError("--smooth " + format_number(half_width_decades) + " is not allowed; the half width must be > 0 decades");
  std::vector<double> ts, lt, le;
  for (std::size_t i = 0; i < data.t.size(); ++i) {
    if (!(data.t[i] > 0)) continue;
    if (!(data.E[i] > 0))
      throw InputError("local slope: E = " + format_number(data.E[i]) + " at t = " + format_number(data.t[i]) +
                       " is not > 0, so ln E is undefined");
    if (!ts.empty() && data.t[i] <= ts.back())
      throw InputError("local slope: t must increase down the table, but " + format_number(data.t[i]) +
                       " follows " + format_number(ts.back()));
    ts.push_back(data.t[i]);
    lt.push_back(std::log(data.t[i]));
    le.push_back(std::log(data.E[i]));
  }
  const double h = half_width_decades * std::log(10.0);
  std::vector<SlopePoint> out;
  std::size_t lo = 0, hi = 0;  // the window [lo, hi) slides with i (t increasing)
  const double slack = 1e-9 * h;  // grid points exactly h apart still count as inside
  for (std::size_t i = 0; i < lt.size(); ++i) {
    // A window may hold millions of rows (10^7 in a table): a look before each fit.
    throw_if_interrupted("during the local slope; no table written");
    // A one-sided window near either end would be biased to first order in h.
    if (lt[i] - h < lt.front() - slack || lt[i] + h > lt.back() + slack) continue;
    while (lt[lo] < lt[i] - h - slack) ++lo;
    while (hi < lt.size() && lt[hi] <= lt[i] + h + slack) ++hi;
    if (hi - lo < 3) continue;
    double c0, c1, cov00, cov01, cov11, ss;
    gsl_fit_linear(&lt[lo], 1, &le[lo], 1, hi - lo, &c0, &c1, &cov00, &cov01, &cov11, &ss);
    if (std::isfinite(c1)) out.push_back({ts[i], -c1});
  }
  if (out.empty())
    throw InputError("local slope: no sample has 3 points within +-" + format_number(half_width_decades) +
                     " decades; widen --smooth or use a finer table");
  return out;
}

}  // namespace coolgas
