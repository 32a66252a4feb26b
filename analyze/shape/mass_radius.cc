#include "analyze/shape/mass_radius.h"

#include <cmath>

#include "analyze/bins/log_bins.h"
#include "analyze/curves/power_law.h"

namespace coolgas {

namespace {

struct BinSums {
  std::int64_t count = 0;
  double ln_m = 0, ln_rg = 0, ln_rg2 = 0, a = 0, p = 0;
};

}  // namespace

MassRadius mass_radius(const std::vector<ClusterShape>& clusters, int per_decade, const Window& fit) {
  MassRadius out;
  std::int64_t top = 1, total = 0, wrapping = 0;
  for (const ClusterShape& c : clusters) {
    top = std::max(top, c.shape.mass);
    total += c.shape.mass;
    if (c.wraps) wrapping += c.shape.mass;
  }
  out.wrapping_fraction = total ? double(wrapping) / double(total) : 0.0;
  const LogBins bins(per_decade, top);
  std::vector<BinSums> sums(static_cast<std::size_t>(bins.size()));
  double fitted_mass = 0;
  for (const ClusterShape& c : clusters) {
    if (c.wraps || !(c.shape.Rg > 0)) continue;
    const int k = bins.index(c.shape.mass);
    BinSums& s = sums[k];
    const double lr = std::log(c.shape.Rg);
    ++s.count;
    s.ln_m += std::log(double(c.shape.mass));
    s.ln_rg += lr;
    s.ln_rg2 += lr * lr;
    s.a += c.shape.asphericity;
    s.p += c.shape.prolateness;
    if (fit.contains(double(c.shape.mass))) {
      ++out.fitted_clusters;
      fitted_mass += double(c.shape.mass);
      out.asphericity += double(c.shape.mass) * c.shape.asphericity;
      out.prolateness += double(c.shape.mass) * c.shape.prolateness;
    }
  }
  if (fitted_mass > 0) out.asphericity /= fitted_mass, out.prolateness /= fitted_mass;
  FitData line;
  for (int k = 0; k < bins.size(); ++k) {
    const BinSums& s = sums[k];
    if (s.count == 0) continue;
    const double n = double(s.count), mean = s.ln_rg / n;
    const double var = s.count > 1 ? std::max(0.0, (s.ln_rg2 - n * mean * mean) / (n - 1)) : 0.0;
    MassRadiusBin b{std::exp(s.ln_m / n), bins.width(k), s.count, std::exp(mean), 0, s.a / n, s.p / n};
    b.Rg_err = b.Rg * std::sqrt(var / n);
    out.bins.push_back(b);
    if (fit.contains(b.m)) line.t.push_back(b.m), line.E.push_back(b.Rg);
  }
  out.fit_bins = int(line.t.size());
  if (out.fit_bins >= 3) {
    // R_g = A m^-theta, so 1/d_f = -theta.
    const PowerLawFit f = fit_power_law(line);
    out.d_f = -1 / f.theta;
    out.d_f_err = f.theta_err / (f.theta * f.theta);
  }
  return out;
}

}  // namespace coolgas
