// The late-time exponent eta of the scaling function, f(x) ~ x^-eta for
// x >> 1 (the paper finds eta = 1.83): a power-law fit to the scaled points
// of all curves pooled, within a window of x.
#pragma once
#include <optional>
#include <vector>

#include "analyze/collapse/curves.h"
#include "analyze/curves/power_law.h"

namespace coolgas {

// The result's theta field is eta. Unweighted; nullopt, with a note on
// stderr, if fewer than 3 points fall in the window.
std::optional<PowerLawFit> fit_tail_exponent(const std::vector<ScalingCurve>& curves, double theta, double z, const Window& x_window);

}  // namespace coolgas
