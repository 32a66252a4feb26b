#include "analyze/collapse/tail.h"

#include <cmath>

#include "common/error.h"

namespace coolgas {

PowerLawFit fit_tail_exponent(const std::vector<ScalingCurve>& curves, double theta, double z, const Window& x_window) {
  FitData d;
  for (const auto& c : curves) {
    for (std::size_t i = 0; i < c.t.size(); ++i) {
      const double x = std::exp(c.ln_t[i] + c.ln_x_shift(z));
      if (!x_window.contains(x)) continue;
      d.t.push_back(x);
      d.E.push_back(std::exp(c.ln_E[i] + c.ln_y_shift(theta, z)));
    }
  }
  if (d.t.size() < 3)
    throw InputError("--eta-window " + x_window.text() + " holds " + std::to_string(d.t.size()) +
                     " scaled points (x = t/L^z); the tail fit needs at least 3");
  return fit_power_law(d);
}

}  // namespace coolgas
