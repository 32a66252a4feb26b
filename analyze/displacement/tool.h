// coolgas-displacement: the mean-square displacement and the velocity
// autocorrelation of every dump of a trajectory from a reference dump
// (data-schema/tsv-tables.md, "coolgas-displacement").
#pragma once
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace coolgas {

struct DisplacementOptions {
  std::string input;            // trajectory file
  std::optional<double> from;   // --from: the reference dump's time; none = the first dump
  std::vector<double> times;    // rows at the dumps nearest these times; empty = every dump from the reference on
  bool exact_time = false;      // --exact-time: refuse a time no dump has
};

// Writes the table for opt to out. InputError on bad input; nothing is
// written unless every dump was read.
void run_displacement(const DisplacementOptions& opt, std::ostream& out);

}  // namespace coolgas
