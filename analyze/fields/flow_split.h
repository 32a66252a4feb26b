// The flow field split by FFT into its longitudinal (compressive) and
// transverse (vortical, shear) parts. The field is the cells' momentum
// density j_c (cell_fields.h) seen as the flow u = j / M_cell of a gas of
// uniform density (M_cell = M / cells), as in Brito & Ernst, Europhys. Lett.
// 43, 497 (1998):
//   j_L(k) = (k.j(k)) k / k^2,  j_T(k) = j(k) - j_L(k),
//   E_L = sum_{k != 0} |j_L(k)|^2 / (2 M^2),  E_T likewise (per unit mass;
//   by Parseval E_L + E_T = sum_c |j_c|^2 / (2 M_cell M)),
//   <|w|^2> = sum_k k^2 |j_T(k)|^2 / M_cell^2 / cells^2, the mean square
//   vorticity w = curl u over the cells.
// For velocities independent of the positions at temperature T (an
// equilibrium gas), <sum_c |j_c|^2> = d T (M - sum_c M_c^2 / M) exactly, a
// share 1/d of it longitudinal: the noise levels below. In 1D there is no
// transverse direction: E_T and the vorticity are 0.
#pragma once
#include <cstdint>
#include <vector>

#include "analyze/fields/cell_fields.h"
#include "analyze/fourier/fourier_grid.h"

namespace coolgas {

// Modes with s - 1/2 <= |k| L / 2 pi < s + 1/2.
struct FlowShell {
  int shell = 0;
  double k = 0;  // mean |k| of its modes [1/sigma]
  double longitudinal = 0, transverse = 0;  // their energies per unit mass
  std::int64_t modes = 0;  // modes in the shell, k and -k counted apart
};

struct FlowSplit {
  double longitudinal = 0, transverse = 0;              // per unit mass
  double longitudinal_noise = 0, transverse_noise = 0;  // the same for independent velocities at `temperature`
  double vorticity2 = 0;                                // mean |curl u|^2 over the cells [omega0^2]
  std::vector<FlowShell> shells;                        // 1 .. n/2
};

// `grid` has f.n points per side in f's geometry; `temperature` sets the noise levels.
FlowSplit flow_split(const CellFields& f, double temperature, FourierGrid& grid);

}  // namespace coolgas
