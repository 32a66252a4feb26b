#include "analyze/collapse/tail.h"

#include <cmath>

#include "common/tool_main.h"
#include "common/tsv.h"

namespace coolgas {

std::optional<PowerLawFit> fit_tail_exponent(const std::vector<ScalingCurve>& curves, double theta, double z, const Window& x_window) {
  FitData d;
  for (const auto& c : curves) {
    for (std::size_t i = 0; i < c.t.size(); ++i) {
      const double x = std::exp(c.ln_t[i] + c.ln_x_shift(z));
      if (!x_window.contains(x)) continue;
      d.t.push_back(x);
      d.E.push_back(std::exp(c.ln_E[i] + c.ln_y_shift(theta, z)));
    }
  }
  if (d.t.size() < 3) {
    // theta and z are still measured; a pipeline that asked for eta too
    // should get them, with eta = nan, rather than nothing.
    note("--eta-window " + x_window.text() + " holds " + std::to_string(d.t.size()) + " scaled points (x = t/L^z" +
         " with z = " + format_number(z) + "); the tail fit needs at least 3, so eta is nan");
    return std::nullopt;
  }
  return fit_power_law(d);
}

}  // namespace coolgas
