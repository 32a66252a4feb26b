// How well curves of several L collapse under given (theta, z).
//
// Q(theta, z) = mean over all pairs of curves of the mean squared difference
// of ln y between the two, on the overlap of their scaled ln x ranges: each
// curve's points inside the overlap are compared with the other curve,
// interpolated linearly in (ln x, ln y), with weights tapering to 0 over the
// outer tenths of the overlap (so Q is continuous in theta and z). A pair whose overlap is shorter than
// min_overlap_decades (or holds no point) counts kNoOverlapPenalty, so the
// optimiser cannot improve Q by pushing the curves apart.
#pragma once
#include <vector>

#include "analyze/collapse/curves.h"

namespace coolgas {

// An rms mismatch of ln y = 10 (a factor e^10): worse than any pair of
// overlapping curves near a sensible (theta, z), so separating curves never pays.
inline constexpr double kNoOverlapPenalty = 100.0;

double collapse_quality(const std::vector<ScalingCurve>& curves, double theta, double z, double min_overlap_decades);

}  // namespace coolgas
