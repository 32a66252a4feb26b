#include "analyze/energy/grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace coolgas {

std::vector<double> log_time_grid(double t_lo, double t_hi, int per_decade) {
  if (!(t_lo > 0) || !(t_hi >= t_lo) || per_decade < 1) throw std::invalid_argument("log_time_grid: bad range");
  // Relative slack so that a run ending at 10^(k/n) up to round-off keeps that point.
  const double slack = 1e-9;
  const auto k_lo = static_cast<long>(std::ceil(std::log10(t_lo) * per_decade - slack));
  const auto k_hi = static_cast<long>(std::floor(std::log10(t_hi) * per_decade + slack));
  std::vector<double> grid;
  for (long k = k_lo; k <= k_hi; ++k) grid.push_back(std::clamp(std::pow(10.0, double(k) / per_decade), t_lo, t_hi));
  if (grid.empty() || grid.front() > t_lo * (1 + slack)) grid.insert(grid.begin(), t_lo);
  if (grid.back() < t_hi * (1 - slack)) grid.push_back(t_hi);
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  return grid;
}

double interpolate_loglog(const std::vector<double>& t, const std::vector<double>& y, double tq) {
  auto hi = std::lower_bound(t.begin(), t.end(), tq);
  if (hi == t.end()) throw std::out_of_range("interpolate_loglog: time beyond the series");
  const auto i = static_cast<std::size_t>(hi - t.begin());
  if (t[i] == tq) return y[i];
  if (i == 0) throw std::out_of_range("interpolate_loglog: time before the series");
  const double u = std::log(tq / t[i - 1]) / std::log(t[i] / t[i - 1]);
  return y[i - 1] * std::pow(y[i] / y[i - 1], u);
}

}  // namespace coolgas
