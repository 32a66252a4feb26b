// coolgas-snapshot: a picture of the particles at the dump nearest a time,
// coloured by cluster (the paper's Fig. 3, upper panels), and a legend table
// of the coloured clusters on stdout.
#pragma once
#include <iosfwd>
#include <string>

#include "analyze/snapshot/plot.h"
#include "analyze/snapshot/scene.h"

namespace coolgas {

struct SnapshotToolOptions {
  std::string input;
  double time = 0;  // the dump nearest this time is drawn
  bool exact_time = false;  // --exact-time: refuse a time no dump has
  std::string output;
  SnapshotOptions scene;
  int size_px = 900;
  std::string gnuplot = "gnuplot";
};

void run_snapshot(const SnapshotToolOptions& opt, std::ostream& out);

}  // namespace coolgas
