// The one-parameter collapse: the product z theta held at a given value P,
// z optimised and theta = P / z. The paper plots E L^3 against t / L^(5/2):
// z theta = d = 3, the mean-field relation between energy and mass at the
// finite-size crossover (one cluster of all N ~ L^d particles moving with the
// momentum of a random sum, E ~ 1/N). Fitting with the product fixed beside
// the free (theta, z) of optimize.h tells whether the data prefer that
// relation: the fixed fit's quality can only be equal to or worse than the
// free one's, and by how much, with z and theta side by side, is the answer.
// Its z is not a second measurement of z: the power-law part of E(t)
// collapses at any z once theta is right (E = A t^-theta gives E L^(z theta)
// = A (t/L^z)^-theta), so Q's valley runs along z at nearly fixed theta and
// the line z theta = P crosses it near z = P/theta, about as precise as
// theta (on the demo's runs z = 2.495 +- 0.022 against the free 2.34 +- 0.14).
//
// Kept apart from optimize.cc (its own minimiser and jackknife) so that the
// free fit's code is untouched by it.
#pragma once
#include <vector>

#include "analyze/collapse/ensemble.h"
#include "analyze/collapse/optimize.h"

namespace coolgas {

// z minimising the collapse quality Q(P/z, z) (quality.h) from search.z0, by
// the one-dimensional Nelder-Mead simplex restarted until Q stops improving
// (as optimize.cc does); theta = P / z, so theta * z is P to rounding.
// Errors: the stratified jackknife over whole runs of optimize.h (kRuns),
// which needs two or more runs of every size: otherwise InputError unless
// search.bootstrap = 0 (the fit without errors). theta_err = P z_err / z^2
// follows from the replicas' theta = P / z_r. InputError as optimize_collapse
// for fewer than 2 sizes, P not finite and > 0, or curves that never overlap.
CollapseFit optimize_collapse_fixed_product(const std::vector<SizeEnsemble>& sizes, const CollapseSearch& search,
                                            double product);

}  // namespace coolgas
