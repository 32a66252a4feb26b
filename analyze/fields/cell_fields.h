// The coarse-grained fields of one frame: the box cut into n^d cubic cells
// (squares, segments), each particle counted in the cell that holds its
// centre (nearest grid point: a field is its cell's sum or average, with no
// further smoothing). Velocities are taken relative to the centre of mass,
// so a uniform translation of the whole gas has no flow at all.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "common/geometry.h"

namespace coolgas {

struct CellFields {
  int n = 0;       // cells per side
  Geometry g{3};
  double L = 0;    // box side [sigma]
  std::int64_t particles = 0;
  double total_mass = 0;
  // Per cell c = ix + n (iy + n iz): particles, their mass, momentum (3
  // components, those beyond d zero) and kinetic energy, all relative to
  // the centre of mass.
  std::vector<double> count, mass, momentum, kinetic;

  std::int64_t cells() const { return std::int64_t(count.size()); }
  double cell_side() const { return L / n; }
  int occupied() const;
  // Flow velocity of cell c, component a: momentum / mass (0 in an empty cell).
  double flow(std::int64_t c, int a) const { return mass[c] > 0 ? momentum[3 * c + a] / mass[c] : 0; }
};

// Cell c's granular temperature, 2 (K_c - |p_c|^2 / 2 M_c) / (d (n_c - 1)),
// for n_c >= 2, else 0.
double cell_temperature(const CellFields& f, std::int64_t c);
// Cell c's vorticity, the curl of the flow velocity by central differences
// over the neighbouring cells (periodic): 3 components, those that need an
// axis beyond d zero (2D: only z; 1D: none).
std::array<double, 3> cell_vorticity(const CellFields& f, std::int64_t c);

// Positions and velocities x0 y0 z0 x1 ...; masses one per particle (empty:
// 1 each). Positions are wrapped into the box first.
CellFields cell_fields(int n, Geometry g, double L, std::span<const double> positions,
                       std::span<const double> velocities, std::span<const double> masses);

// Energies of the fields, per unit mass (per particle for unit masses).
struct FieldEnergies {
  double kinetic = 0;      // (1/M) sum m v^2 / 2
  double flow = 0;         // (1/M) sum_cells |p_c|^2 / (2 M_c): the cells' mean motion
  double thermal = 0;      // kinetic - flow: what is left after the local flow is removed
  double temperature = 0;  // 2 thermal M / (d (N - occupied cells)): each cell's mean takes d degrees of freedom
  double flow_noise = 0;   // (d/2) temperature (occupied - 1) / M: the flow of independent velocities
  double density_variance = 0;  // Var(count) / <count> over the cells: 1 for independent positions
};
FieldEnergies field_energies(const CellFields& f);

}  // namespace coolgas
