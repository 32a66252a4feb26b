#include "analyze/velocity/distribution.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.h"
#include "common/tsv.h"

namespace coolgas {

// kappa + (d+2)/d = R = a / b² with a = <s⁴>, b = <s²> (s the speed). Its
// standard error by the delta method (first-order expansion of R in the sample means):
//   Var(R) = [Var(s⁴)/b⁴ - 4a Cov(s⁴, s²)/b⁵ + 4a² Var(s²)/b⁶] / N.
// For a Maxwellian in 3D (s² ~ χ²₃ in units of T: moments 3, 15, 105, 945)
// this is 40/(27 N); in 2D (χ²₂: 2, 8, 48, 384) it is 4/N; in 1D (χ²₁:
// 1, 3, 15, 105) it is 24/N. The velocity tests check all three values.
SpeedMoments speed_moments(std::span<const double> v, Geometry g) {
  const int dimension = g.d();
  const std::size_t n = v.size() / 3;
  if (n < 2) throw InputError("velocity statistics need at least 2 particles, got " + std::to_string(n));
  auto speed2 = [&](std::size_t p) {
    return v[3 * p] * v[3 * p] + v[3 * p + 1] * v[3 * p + 1] + v[3 * p + 2] * v[3 * p + 2];
  };
  double sum2 = 0, sum4 = 0;
  for (std::size_t p = 0; p < n; ++p) {
    const double s2 = speed2(p);
    sum2 += s2;
    sum4 += s2 * s2;
  }
  const double N = double(n), b = sum2 / N, a = sum4 / N;
  if (!(b > 0)) throw InputError("all velocities are zero: v_rms = 0, the scaled distribution is undefined");
  double var2 = 0, var4 = 0, cov = 0;  // second pass: centred sums, accurate for large N
  for (std::size_t p = 0; p < n; ++p) {
    const double d2 = speed2(p) - b, d4 = speed2(p) * speed2(p) - a;
    var2 += d2 * d2;
    var4 += d4 * d4;
    cov += d2 * d4;
  }
  var2 /= N - 1;
  var4 /= N - 1;
  cov /= N - 1;
  const double var_r = (var4 / std::pow(b, 4) - 4 * a * cov / std::pow(b, 5) + 4 * a * a * var2 / std::pow(b, 6)) / N;
  const SpeedMoments m{std::int64_t(n), std::sqrt(b / dimension), a / (b * b) - maxwellian_speed_ratio(dimension),
                       std::sqrt(std::max(var_r, 0.0))};
  // kappa's error sums s^8: velocities beyond about 1e38 overflow it, and the
  // table would hold inf or nan (issue 52). Refused, naming the largest.
  if (!(std::isfinite(m.v_rms) && std::isfinite(m.kappa) && std::isfinite(m.kappa_err))) {
    double largest = 0;
    for (const double x : v) largest = std::max(largest, std::fabs(x));
    throw InputError("velocities up to |v| = " + format_number(largest) +
                     " overflow their moments (kappa's error sums |v|^8); give velocities below 1e38");
  }
  return m;
}

ComponentHistogram::ComponentHistogram(int bins, double ymax) : ymax_(ymax) {
  // More bins than 1e6 hold no sample each even for N = 1e8 particles, and cost memory and time per dump.
  if (bins < 2 || bins % 2 != 0 || bins > 1000000)
    throw InputError("--bins must be even and in [2, 1000000] (bins mirror about y = 0), got " + std::to_string(bins));
  if (!(ymax > 0) || !std::isfinite(ymax))
    throw InputError("--ymax must be a positive number, got " + format_number(ymax));
  width_ = 2 * ymax / bins;
  count_.assign(static_cast<std::size_t>(bins), 0);
}

void ComponentHistogram::fill(std::span<const double> v, double v_rms, Geometry g) {
  std::fill(count_.begin(), count_.end(), 0);
  const std::size_t d = static_cast<std::size_t>(g.d());
  samples_ = static_cast<std::int64_t>(v.size() / 3 * d);
  const double scale = 1.0 / (v_rms * width_);
  const double nb = double(count_.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i % 3 >= d) continue;  // a 2D file's vz = 0 is no sample, nor a 1D file's vy and vz
    const double u = v[i] * scale + 0.5 * nb;  // bin coordinate: 0 at y = -ymax
    if (u >= 0 && u < nb) ++count_[static_cast<std::size_t>(u)];
  }
}

}  // namespace coolgas
