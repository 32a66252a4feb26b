// coolgas-snapshot: a picture of the particles at the dump nearest a time,
// coloured by cluster (the paper's Fig. 3, upper panels), and a legend table
// of the coloured clusters on stdout. A 1D file is drawn as a space-time
// diagram of its dumps up to that time (space_time.h), with a table of one
// row per dump.
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

#include "analyze/snapshot/plot.h"
#include "analyze/snapshot/scene.h"

namespace coolgas {

struct SnapshotToolOptions {
  std::string input;
  std::vector<double> times;  // --time: exactly one; the dump nearest it is drawn
  bool exact_time = false;    // --exact-time: refuse a time no dump has
  std::string output;
  bool force = false;  // --force: replace an existing picture
  SnapshotOptions scene;
  std::string only_3d;  // "--view 3d", "--thickness 4" when given: options a 2D or 1D file refuses
  std::string not_1d;   // "--colored 3", "--max-points 10" when given: options a 1D file refuses
  int size_px = 900;
  std::string gnuplot = "gnuplot";
};

void run_snapshot(const SnapshotToolOptions& opt, std::ostream& out);

}  // namespace coolgas
