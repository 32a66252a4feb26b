// coolgas-clusters: the cluster statistics of every dump of a trajectory, as
// the shared "mass distribution" or "cluster series" table
// (data-schema/tsv-tables.md, "Shared table shapes").
#pragma once
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace coolgas {

struct ClustersOptions {
  std::string input;          // trajectory file
  std::string definition = "cells";  // --definition: cells, contact or contact:CUTOFF (cluster_definition.h)
  int bins_per_decade = 10;   // logarithmic mass bins
  bool series = false;        // one row per dump instead of N(m) blocks
  bool scaled = false;        // N(m) blocks with only t, x = m/M_avg, y = N M_avg^2 (paper Fig. 3)
  std::vector<double> times;  // dumps nearest these times; empty = all dumps
  bool exact_time = false;  // --exact-time: refuse a time no dump has
  // --species K: the clusters of a mixture's species K alone (its index in
  // the file: 0 for the first [[species]] table); absent: every particle.
  std::optional<int> species;
};

// Writes the table for opt to out. InputError on bad input.
void run_clusters(const ClustersOptions& opt, std::ostream& out);

}  // namespace coolgas
