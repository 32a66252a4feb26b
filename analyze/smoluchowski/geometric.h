// The long-time method: a sectional scheme on a geometric mass grid, the
// fixed-pivot technique of Kumar & Ramkrishna, Chem. Eng. Sci. 51, 1311 (1996).
//
// Grid: the pivots are the integers 1, 2, 3, ... while the ratio between
// neighbours exceeds `ratio`, then grow geometrically, x_{i+1} = round(r x_i),
// up to the cut-off M (the last pivot). Cell i holds N_i, the clusters per
// unit volume with masses between the midpoints to its neighbours, all
// counted at the pivot x_i. A pair of cells (i, j) coalescing makes mass
// v = x_i + x_j; falling between pivots x_k <= v < x_{k+1} it is shared as
//   η = (x_{k+1} − v)/(x_{k+1} − x_k) to cell k,  1 − η to cell k+1,
// which conserves both the number of new clusters and their mass exactly
// (a finite-volume-like conservative split), so total mass changes only by
// what crosses the cut-off. On the integer part of the grid the scheme is the
// discrete equation itself; with a ratio small enough that all pivots are
// integers it reproduces DirectRhs exactly.
//
// Accuracy traded for speed: about log(M)/log(r) cells instead of M, O(cells^2)
// per right-hand side; the distribution is smeared over a cell, and errors
// grow with r (measured by the accuracy study).
#pragma once
#include "analyze/smoluchowski/grid.h"
#include "analyze/smoluchowski/powers.h"

namespace coolgas::smoluchowski {

// Pivots and cells for a cut-off M and a growth ratio r > 1 (InputError otherwise).
MassGrid geometric_grid(std::int64_t M, double ratio);

class GeometricRhs : public CoagulationRhs {
 public:
  GeometricRhs(const Kernel& kernel, std::int64_t M, double ratio);
  const MassGrid& grid() const override { return grid_; }
  void evaluate(const double* c, double* dcdt) override;

 private:
  MassGrid grid_;
  KernelPowers powers_;
};

}  // namespace coolgas::smoluchowski
