// The static structure factor of a weighted set of points in a periodic box,
//   S(k) = |sum_j m_j e^{-i k.r_j}|^2 / sum_j m_j,   k = (2 pi / L) (a, b, c), integer a, b, c,
// averaged over spherical shells of |k| (in 2D: k = (2 pi / L) (a, b), circles; in 1D: k = 2 pi a / L, the
// shell s is the mode a = s and its mirror -s): shell s holds the modes with
// s - 1/2 <= |k| L / (2 pi) < s + 1/2, s = 1 .. n/4 (up to half the Nyquist
// wave number k_N = pi n / L of the grid; k = 0 is left out). Beyond k_N/2
// the correction below fails: along an axis its shot-noise residual
// s (1 - C1/W^2) is -0.015 s at k_N/2 but -0.75 s at k_N; a finer grid
// reaches larger k.
// With unit weights this is the structure factor of the particles; with the
// aggregates' masses it is that of their particles, each at its aggregate's centre.
//
// From the cloud-in-cell grid (cloud_in_cell.h) each mode is estimated as
//   S(k) = s + (|rho_grid(k)|^2 / M - s C1(k)) / W^2(k),   s = sum m_j^2 / M,  M = sum m_j:
// the shot noise of the aliased images, s C1(k), is subtracted exactly and
// the principal image's window is divided out (Jing, ApJ 620, 559 (2005);
// the aliased signal, sum over n != 0 of W^2 (S - s), is neglected).
// What remains differs from the exact sum by the cross terms of the principal
// image with its aliases, of typical size
//   |S_grid - S_exact| ~ 2 (1/W(k) - 1) sqrt(s S(k))
// (the aliases hold the weight 1/W - 1 relative to it, each with |rho|^2 ~ s M):
// 1/W - 1 = (pi^2/3)(|k| L / 2 pi n)^2 to leading order, so 2 (1/W - 1) is
// 6e-3 at the lowest shell of a 32^3 grid and 1e-4 on 272^3.
#pragma once
#include <span>
#include <vector>

#include "analyze/fourier/fourier_grid.h"

namespace coolgas {

struct Shell {
  int index = 0;      // s: |k| L / 2 pi rounded
  double k = 0;       // mean |k| of its modes [1/sigma]
  double S = 0;       // mean of S over its modes
  double S_err = 0;   // standard error of that mean: spread of S over the shell's independent modes
  double modes = 0;   // independent modes (k and -k count once)
};

// Point weights: total M = sum m_j, and s = sum m_j^2 / M (1 for unit weights).
struct Weights {
  double total = 0, shot = 1;
};
Weights weights_of(std::span<const double> weights, std::size_t points);

// Shells 1 .. n/4 of S(k) from a grid that holds the CIC assignment of the
// points after FourierGrid::forward(). Shells without modes are left out.
std::vector<Shell> shell_average(const FourierGrid& grid, double L, const Weights& w);

// The exact S(k) of the points, averaged over the same modes, for shells
// 1 .. max_shell: O(points * modes), the check of shell_average. In 2D
// (dimension 2; every z is 0) the modes have c = 0, in 1D b = c = 0 too.
std::vector<double> direct_structure_factor(double L, std::span<const double> positions,
                                            std::span<const double> weights, int max_shell, Geometry g);

// Shell of the integer wave vector with a^2 + b^2 + c^2 = m2: round(sqrt(m2)).
int shell_of(long m2);

}  // namespace coolgas
