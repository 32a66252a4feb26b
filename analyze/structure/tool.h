// coolgas-structure: the structure factor S(k, t), the growing length L_t and
// the correlation lengths of the coarse-grained density and momentum fields of
// every dump of a trajectory (data-schema/tsv-tables.md, "coolgas-structure").
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace coolgas {

enum class StructureTable { kSpectrum, kSeries, kCorrelation };

struct StructureOptions {
  std::string input;                 // trajectory file
  StructureTable table = StructureTable::kSpectrum;
  int grid = 0;                      // grid points per side; 0: the even number nearest below L (spacing ~ sigma)
  double peak_fraction = 0.1;        // the cut of the low-k peak (growing_length.h)
  int direct_shells = 1;             // shells checked against the exact sum over particles (0: none)
  std::vector<double> times;         // dumps nearest these times; empty = all dumps
  bool exact_time = false;  // --exact-time: refuse a time no dump has
};

// Writes the table for opt to out. InputError on bad input; nothing is
// written unless every dump was read.
void run_structure(const StructureOptions& opt, std::ostream& out);

}  // namespace coolgas
