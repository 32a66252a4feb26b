// How well curves of several L collapse under given (theta, z).
//
// Q(theta, z) = mean over all pairs of curves of the mean squared difference
// of ln y between the two, on the overlap of their scaled ln x ranges: each
// curve's points inside the overlap are compared with the other curve,
// interpolated linearly in (ln x, ln y), with weights tapering to 0 over the
// outer tenths of the overlap (so Q is continuous in theta and z). A pair whose overlap is shorter than
// min_overlap_decades (or holds no point) counts kNoOverlapPenalty, so the
// optimiser cannot improve Q by pushing the curves apart. Curves weighted
// by the scatter of their runs (seed_weights.h) compare (ln y_a - ln y_b)^2
// over var_a + var_b instead: Q is then a chi^2 per point.
#pragma once
#include <vector>

#include "analyze/collapse/curves.h"

namespace coolgas {

// An rms mismatch of ln y = 10 (a factor e^10): worse than any pair of
// overlapping curves near a sensible (theta, z), so separating curves never pays.
inline constexpr double kNoOverlapPenalty = 100.0;
// Weighted (a chi^2 per point, seed_weights.h): a mismatch of 1e3 standard errors.
inline constexpr double kWeightedNoOverlapPenalty = 1e6;
inline double no_overlap_penalty(bool weighted) { return weighted ? kWeightedNoOverlapPenalty : kNoOverlapPenalty; }

double collapse_quality(const std::vector<ScalingCurve>& curves, double theta, double z, double min_overlap_decades);

}  // namespace coolgas
