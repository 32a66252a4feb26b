// coolgas-shape: the shapes of the clusters of every dump of a trajectory
// (gyration tensor, R_g, asphericity, prolateness) and their mass-radius
// relation M ~ R_g^{d_f} (data-schema/tsv-tables.md, "coolgas-shape").
#pragma once
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace coolgas {

enum class ShapeTable { kMassRadius, kSeries, kClusters };

struct ShapeOptions {
  std::string input;            // trajectory file
  ShapeTable table = ShapeTable::kMassRadius;
  int bins_per_decade = 10;     // logarithmic mass bins
  std::string fit_mass = "10:"; // mass window of the d_f fit, "lo:hi" [particles]
  std::int64_t min_mass = 10;   // --clusters: smallest cluster listed [particles]
  std::vector<double> times;    // dumps nearest these times; empty = all dumps
  bool exact_time = false;  // --exact-time: refuse a time no dump has
};

void run_shape(const ShapeOptions& opt, std::ostream& out);

}  // namespace coolgas
