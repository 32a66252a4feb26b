// The tail of the scaled velocity distribution: the paper (Pathak et al.
// 2014, Fig. 5 lower inset) finds -ln Φ(y) ~ y^β at large y, β ≈ 5/3 for the
// clustered granular gas and 0.70 for ballistic aggregation.
//
// β is fitted by weighted linear least squares of ln(-ln Φ) against ln y over
// the tail bins (y >= y_from, both signs folded together, at least
// `min_count` samples). Each point's weight is its inverse Poisson variance:
// σ[ln(-ln Φ)] = 1 / (√count · |ln Φ|).
#pragma once
#include <optional>
#include <vector>

#include "analyze/velocity/distribution.h"

namespace coolgas {

struct TailPoint {
  double y = 0;      // bin centre, > 0
  double phi = 0;    // Φ at y, averaged over +y and -y
  double count = 0;  // samples in the two mirrored bins
};

struct TailFit {
  double beta = 0, beta_err = 0;  // exponent and its standard error
  double prefactor = 0;           // c in -ln Φ = c y^β
  int points = 0;
};

// The folded tail bins that qualify for the fit, in increasing y.
std::vector<TailPoint> tail_points(const ComponentHistogram& h, double y_from, double min_count);

// The fit; nothing if fewer than 3 points. The error is the fit's standard
// error, scaled up by sqrt(χ²/dof) when the points scatter more than their
// Poisson errors say.
std::optional<TailFit> fit_tail(const std::vector<TailPoint>& points);

}  // namespace coolgas
