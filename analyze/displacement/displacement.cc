#include "analyze/displacement/displacement.h"

#include <cmath>

#include "common/compensated_sum.h"

namespace coolgas {

namespace {

// <|v|^2>/d over the particles.
double temperature_of(std::span<const double> v, Geometry g) {
  CompensatedSum s;
  for (double x : v) s.add(x * x);
  return v.empty() ? 0.0 : s.value() / double(v.size() / 3) / g.d();
}

}  // namespace

DisplacementOrigin::DisplacementOrigin(double L, std::span<const double> positions,
                                       std::span<const std::int32_t> images, std::span<const double> velocities,
                                       Geometry g)
    : g_(g), unwrapped_(positions.size()), velocity_(velocities.begin(), velocities.end()) {
  for (std::size_t k = 0; k < positions.size(); ++k) unwrapped_[k] = positions[k] + L * double(images[k]);
  T_ = temperature_of(velocities, g);
}

Displacement DisplacementOrigin::from_here(double L, std::span<const double> positions,
                                           std::span<const std::int32_t> images,
                                           std::span<const double> velocities) const {
  const std::size_t n = particles();
  CompensatedSum sum, sum2, vv;
  for (std::size_t i = 0; i < n; ++i) {
    double r2 = 0, dot = 0;
    for (std::size_t k = 3 * i; k < 3 * i + 3; ++k) {
      const double dx = positions[k] + L * double(images[k]) - unwrapped_[k];
      r2 += dx * dx;
      dot += velocities[k] * velocity_[k];
    }
    sum.add(r2), sum2.add(r2 * r2), vv.add(dot);
  }
  Displacement d;
  d.d = g_.d();
  if (n == 0) return d;
  d.msd = sum.value() / double(n);
  const double var = n > 1 ? (sum2.value() / double(n) - d.msd * d.msd) * double(n) / double(n - 1) : 0.0;
  d.msd_err = var > 0 ? std::sqrt(var / double(n)) : 0.0;
  d.vacf = vv.value() / double(n);
  d.vacf_norm = T_ > 0 ? d.vacf / (g_.d() * T_) : 0.0;
  d.T = temperature_of(velocities, g_);
  return d;
}

}  // namespace coolgas
