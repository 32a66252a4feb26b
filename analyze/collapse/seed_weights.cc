#include "analyze/collapse/seed_weights.h"

#include <algorithm>
#include <cmath>

#include "common/error.h"
#include "common/tsv.h"

namespace coolgas {
namespace {

// The 2k+1-row moving average, shorter at the ends.
std::vector<double> moving_average(const std::vector<double>& v, int k) {
  std::vector<double> out(v.size());
  const auto n = static_cast<std::ptrdiff_t>(v.size());
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const std::ptrdiff_t lo = std::max<std::ptrdiff_t>(0, i - k), hi = std::min(n - 1, i + k);
    double sum = 0;
    for (std::ptrdiff_t j = lo; j <= hi; ++j) sum += v[std::size_t(j)];
    out[std::size_t(i)] = sum / double(hi - lo + 1);
  }
  return out;
}

}  // namespace

void estimate_seed_scatter(SizeEnsemble& e) {
  const std::size_t n = e.runs.size();
  if (n < 2)
    throw InputError("--weights seeds needs two or more tables (runs) of every L; L = " + format_number(e.L) +
                     " has " + std::to_string(n));
  e.scatter = {};
  const ScalingCurve mean = ensemble_mean(e);  // its ln_E_err is the standard error of the mean of E, over E
  std::vector<double> var(mean.t.size());
  for (std::size_t i = 0; i < var.size(); ++i) {
    const double se = mean.ln_E_err[i];
    var[i] = se * se * double(n);  // one run's variance (delta method: var ln E = var E / E^2)
  }
  var = moving_average(var, kScatterRows);
  for (double& v : var) v = std::max(v, kScatterFloor * kScatterFloor);
  e.scatter = {mean.ln_t, var};
}

std::vector<double> mean_ln_E_variance(const SizeEnsemble& e, const std::vector<double>& ln_t, std::size_t runs) {
  if (e.scatter.ln_t.empty()) return {};
  std::vector<double> out;
  for (double lt : ln_t) out.push_back(interpolate_clamped(e.scatter.ln_t, e.scatter.var, lt) / double(runs));
  return out;
}

}  // namespace coolgas
