// The runs (seeds) of one system size and their mean E(t) curve.
//
// A finite-size-scaling study resamples whole runs when it estimates the
// errors of theta and z: the E(t) of one run is strongly correlated in time
// (a run that happens to cluster early stays above the mean for decades), so
// treating its points as independent, as a bootstrap over points or over the
// errors of a mean does, underestimates the errors and does not shrink them
// as runs are added. Keeping the runs apart makes the resampling possible.
#pragma once
#include <cstddef>
#include <vector>

#include "analyze/collapse/curves.h"

namespace coolgas {

// The variance of one run's ln E about the mean of its size, at the times
// ln_t (seed_weights.h); empty unless the collapse is weighted.
struct SeedScatter {
  std::vector<double> ln_t, var;
};

struct SizeEnsemble {
  double L = 0;
  std::vector<ScalingCurve> runs;  // one per input table of this L, in input order
  SeedScatter scatter;
};

// Curves grouped by L, in increasing L.
std::vector<SizeEnsemble> group_by_size(const std::vector<ScalingCurve>& curves);

// The mean of the runs at `picks` (indices into e.runs; repeats allowed) at
// the times every picked run has (relative tolerance 1e-9): E averaged,
// ln_E_err the standard error of that mean over E when two or more runs are
// picked, else the single run's own errors; ln_E_var from e.scatter (over the
// number picked) when it has one. InputError if the picked runs share fewer
// than 2 times.
ScalingCurve ensemble_mean(const SizeEnsemble& e, const std::vector<std::size_t>& picks);
ScalingCurve ensemble_mean(const SizeEnsemble& e);  // every run once

// The mean curve of every size, in increasing L.
std::vector<ScalingCurve> mean_curves(const std::vector<SizeEnsemble>& sizes);

// The size without its run r, for the jackknife over runs. Weights, when the
// collapse has them, are estimated again from the runs left (if two or more
// are), so that their dependence on the data is resampled too; with one left
// it keeps the scatter of all of them.
SizeEnsemble without_run(const SizeEnsemble& e, std::size_t r);

// Sum of squared deviations from the mean (the replicas' spread).
double sum_of_squares(const std::vector<double>& v);

}  // namespace coolgas
