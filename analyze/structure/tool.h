// coolgas-structure: the structure factor S(k, t), the growing length L_t and
// the correlation lengths of the coarse-grained density and momentum fields,
// or the radial distribution function g(r) and its contact value, of every
// dump of a trajectory (data-schema/tsv-tables.md, "coolgas-structure").
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace coolgas {

enum class StructureTable {
  kSpectrum,     // S(k) blocks
  kSeries,       // one row per dump: L_t, L_C, L_v
  kCorrelation,  // C(r), C_v(r) blocks
  kRdf,          // g(r) blocks (--rdf)
  kRdfSeries     // one row per dump: g(sigma+) (--rdf --series)
};
inline bool is_rdf(StructureTable t) { return t == StructureTable::kRdf || t == StructureTable::kRdfSeries; }

struct StructureOptions {
  std::string input;                 // trajectory file
  StructureTable table = StructureTable::kSpectrum;
  int grid = 0;                      // grid points per side; 0: the even number nearest below L (spacing ~ sigma)
  double peak_fraction = 0.1;        // the cut of the low-k peak (growing_length.h)
  int direct_shells = 1;             // shells checked against the exact sum over particles (0: none)
  double r_max = 0;                  // g(r) up to r_max [sigma]; 0: min(5, L/2)
  int bins_per_sigma = 50;           // g(r) bins per sigma
  int contact_bins = 5;              // bins above sigma fitted for g(sigma+)
  std::vector<double> times;         // dumps nearest these times; empty = all dumps
  bool exact_time = false;  // --exact-time: refuse a time no dump has
};

// Writes the table for opt to out. InputError on bad input; nothing is
// written unless every dump was read.
void run_structure(const StructureOptions& opt, std::ostream& out);

}  // namespace coolgas
