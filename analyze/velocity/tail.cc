#include "analyze/velocity/tail.h"

#include <gsl/gsl_fit.h>

#include <algorithm>
#include <cmath>

namespace coolgas {

std::vector<TailPoint> tail_points(const ComponentHistogram& h, double y_from, double min_count) {
  std::vector<TailPoint> out;
  const int nb = h.bins();
  for (int j = nb / 2; j < nb; ++j) {
    const double y = h.center(j);
    const double count = double(h.count(j) + h.count(nb - 1 - j));
    const double phi = 0.5 * (h.phi(j) + h.phi(nb - 1 - j));
    // ln(-ln Φ) needs 0 < Φ < 1.
    if (y >= y_from && count >= min_count && count > 0 && phi < 1) out.push_back({y, phi, count});
  }
  return out;
}

std::optional<TailFit> fit_tail(const std::vector<TailPoint>& points) {
  const std::size_t n = points.size();
  if (n < 3) return std::nullopt;
  std::vector<double> x(n), y(n), w(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double minus_ln_phi = -std::log(points[i].phi);
    x[i] = std::log(points[i].y);
    y[i] = std::log(minus_ln_phi);
    w[i] = points[i].count * minus_ln_phi * minus_ln_phi;
  }
  double c0, c1, cov00, cov01, cov11, chisq;
  gsl_fit_wlinear(x.data(), 1, w.data(), 1, y.data(), 1, n, &c0, &c1, &cov00, &cov01, &cov11, &chisq);
  const double scatter = std::max(1.0, chisq / double(n - 2));
  return TailFit{c1, std::sqrt(cov11 * scatter), std::exp(c0), static_cast<int>(n)};
}

}  // namespace coolgas
