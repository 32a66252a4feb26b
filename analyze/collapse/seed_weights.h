// Weights of the collapse from the scatter of the runs (seeds) of each size.
//
// Unweighted, the collapse quality counts every point alike, and at late
// times (x = t/L^z >> 1) a small box holds a few clusters whose motion makes
// ln E of one run wander by tens of percent (the two runs of L = 48 in the
// demo differ by a factor 4 at t = 1e5): those points then set theta and z,
// and the jackknife over runs swings with them (sigma_z = 3 from 2 seeds per
// L). Weighing each squared difference by the variance of the two curves
// there, as finite-size-scaling collapses with errors do (Houdayer &
// Hartmann, Phys. Rev. B 70, 014418 (2004): a reduced chi^2 per point), lets
// each part of the data count as much as it is known.
//
// The variance of one run's ln E about the mean of its size is estimated at
// each common time from the n runs (ddof 1), averaged over the 2k+1 rows
// around it (k = kScatterRows: with two seeds one time alone is a chi^2 of one
// degree of freedom) and kept above kScatterFloor^2 (ln E is interpolated
// between rows; points known better than 1 % would outweigh everything).
// A mean of m of the runs then has the variance / m at its times. The
// jackknife over runs (optimize.h) estimates the weights again from the runs
// each replica keeps, so that their own noise is resampled; a size with only
// two runs cannot (one run has no scatter) and keeps the weights of both, and
// the errors then come out too small: on the synthetic ensembles of
// tests/unit/analyze/collapse/seed_weights_test.cc one standard error covers
// the truth in about 65-85 % of the ensembles with 3-8 runs per size, but in
// about 40 % with 2.
#pragma once
#include <vector>

#include "analyze/collapse/ensemble.h"

namespace coolgas {

inline constexpr int kScatterRows = 3;
inline constexpr double kScatterFloor = 0.01;

// Fills e.scatter from its runs. InputError if it has fewer than 2 runs, or
// they share fewer than 2 times.
void estimate_seed_scatter(SizeEnsemble& e);

// The variance of ln E of a mean of `runs` runs of e at the times ln_t
// (interpolated in ln t, clamped at the ends); empty if e has no scatter.
std::vector<double> mean_ln_E_variance(const SizeEnsemble& e, const std::vector<double>& ln_t, std::size_t runs);

}  // namespace coolgas
