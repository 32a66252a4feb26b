// Drawing a snapshot scene (simulate/run/scene.h) into a PNG with gnuplot
// (pngcairo terminal). The data and the script go to a temporary directory;
// the PNG is moved to its destination only once gnuplot has succeeded, so a
// failure never leaves a truncated picture behind.
#pragma once
#include <string>

#include "analyze/snapshot/scene.h"

namespace coolgas {

struct PlotOptions {
  std::string title;
  double L = 0;  // box side: axis ranges, and particle size in the slab view
  SnapshotView view = SnapshotView::kSlab;
  int size_px = 900;                // width = height of the picture
  std::string gnuplot = "gnuplot";  // program to run
};

// InputError (one line) if the destination's directory is missing, gnuplot
// cannot be run, or gnuplot fails (quoting its first error line).
void render_png(const SnapshotScene& scene, const PlotOptions& opt, const std::string& output);

}  // namespace coolgas
