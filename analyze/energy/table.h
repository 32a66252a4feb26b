// The coolgas-energy tool: trajectories in, E(t) table out
// (columns and provenance in data-schema/tsv-tables.md, section coolgas-energy).
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace coolgas {

struct EnergyOptions {
  std::vector<std::string> inputs;  // trajectory files, one per seed
  int per_decade = 20;              // grid points per decade of t
};

// Reads every input, checks they share the physics, averages, writes the table.
void write_energy_table(const EnergyOptions& options, std::ostream& out);

}  // namespace coolgas
