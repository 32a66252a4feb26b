// Drawing a snapshot scene (analyze/snapshot/scene.h) into a picture with
// gnuplot's cairo terminals (PNG or PDF) or its SVG terminal, chosen by the
// output's extension. The data and the script go to a temporary directory;
// the picture is moved to its destination only once gnuplot has succeeded,
// so a failure never leaves a truncated picture behind. A key beside the
// picture names each coloured cluster's mass.
#pragma once
#include <filesystem>
#include <functional>
#include <string>

#include "analyze/snapshot/scene.h"

namespace coolgas {

enum class PictureFormat { kPng, kPdf, kSvg };

// The format named by the file's extension (.png, .pdf, .svg, any case);
// InputError for any other.
PictureFormat picture_format(const std::string& output);

struct PlotOptions {
  std::string title;
  double L = 0;  // box side: axis ranges, and particle size in the slab view
  SnapshotView view = SnapshotView::kSlab;
  int size_px = 900;                // height of the picture; the width adds 30 % for the key
  std::string what = "cluster";     // what the colours mark ("cluster" or "aggregate"), for the key
  std::string gnuplot = "gnuplot";  // program to run
  PictureFormat format = PictureFormat::kPng;
};

// InputError (one line) if the destination's directory is missing, gnuplot
// cannot be run, or gnuplot fails (quoting its first error line).
void render_picture(const SnapshotScene& scene, const PlotOptions& opt, const std::string& output);

// What render_picture does for any picture: `write` fills the data file,
// `make_script` returns the gnuplot script drawing it into the picture
// (both in a temporary directory); the same errors.
void render_with_gnuplot(const std::function<void(const std::filesystem::path& data)>& write,
                         const std::function<std::string(const std::filesystem::path& data,
                                                         const std::filesystem::path& picture)>& make_script,
                         const PlotOptions& opt, const std::string& output);

// A gnuplot single-quoted string (a quote is written twice).
std::string gnuplot_quoted(const std::string& s);
// The `set terminal` line's argument for opt.format at `width` x opt.size_px.
std::string gnuplot_terminal(const PlotOptions& opt, int width);

}  // namespace coolgas
