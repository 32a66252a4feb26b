// Initial distributions c_m(0) put on a method's grid.
//   "mono"        c_1 = 1, all other masses empty (the default)
//   a TSV path    first block of a table with columns m and N (c_m per unit
//                 volume); with a dm column as well (coolgas-clusters or
//                 coolgas-smoluchowski output) each bin's N is given to every
//                 integer mass of the bin. "-" reads stdin.
// Masses between two pivots of a geometric grid are shared between them
// conserving number and mass, as the scheme itself does.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "analyze/smoluchowski/grid.h"
#include "common/tsv.h"

namespace coolgas::smoluchowski {

// c_m(0) for integer masses m = 1..(size-1) (index = mass, entry 0 unused).
// A mass (a bin's upper edge) above `cutoff`, the run's --M, is refused
// (InputError naming the row, the mass and M) before anything is allocated
// for it: the vector never holds more than cutoff + 1 entries.
std::vector<double> initial_masses(const std::string& spec, std::int64_t cutoff);
// The same from a table already read (its first block).
std::vector<double> initial_masses(const Table& table, std::int64_t cutoff);

// The same distribution on a grid. InputError if it holds masses above the cut-off.
std::vector<double> on_grid(const MassGrid& grid, const std::vector<double>& by_mass);

}  // namespace coolgas::smoluchowski
