// The local slope -d ln E / d ln t, smoothed: at each sample, the slope of a
// straight-line least-squares fit of ln E against ln t over the samples within
// +-half_width decades of it. A power law A t^-theta gives theta exactly.
#pragma once
#include <vector>

#include "analyze/curves/fit_data.h"

namespace coolgas {

struct SlopePoint {
  double t = 0, slope = 0;
};

// Samples with t <= 0 are skipped. A sample closer than half_width to either
// end of the data (its window would be one-sided), or whose window holds fewer
// than 3 points, gets no slope. InputError if no sample gets one. Errors are not used.
std::vector<SlopePoint> local_slope(const FitData& data, double half_width_decades);

}  // namespace coolgas
