// The common time grid of coolgas-energy and interpolation onto it.
//
// Runs record observables at slightly different times (dump times, t_end, a
// resumed run), so averaging over seeds first brings every run onto one grid:
// t = 10^(k / per_decade), the grid the simulator itself uses, so that runs
// recorded on it are copied without interpolation error.
#pragma once
#include <vector>

namespace coolgas {

// Grid points 10^(k/per_decade) in [t_lo, t_hi] (0 < t_lo <= t_hi), with t_lo
// and t_hi themselves added when they are not grid points (so the overlap of
// the runs is covered to its ends). Increasing.
std::vector<double> log_time_grid(double t_lo, double t_hi, int per_decade);

// Value of y(t) at tq by linear interpolation of ln y against ln t between
// the bracketing samples (power laws are straight lines there). t increasing,
// t > 0 and y > 0 in the bracket, t[0] <= tq <= t.back(); exact at samples.
double interpolate_loglog(const std::vector<double>& t, const std::vector<double>& y, double tq);

}  // namespace coolgas
