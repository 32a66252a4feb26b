// The dimension d of the run a table was made from, as one provenance line
// ("# dimension: 2"). Tables of 3D runs carry no such line, so they read
// exactly as they did before disks existed; a table without it is 3D.
// coolgas-energy writes it, coolgas-fit and coolgas-collapse read it (the
// finite-size crossover and the scaling z = d/theta depend on d).
#pragma once
#include <string>

#include "common/tsv.h"

namespace coolgas {

// Appends "dimension: d" for d != 3; nothing for d = 3.
void add_dimension_line(Provenance& p, int dimension);

// The table's dimension: 3 without the line; InputError naming the table
// and the value when the line is not 1, 2 or 3.
int dimension_of(const Table& table);

}  // namespace coolgas
