#include "analyze/snapshot/tool.h"

#include <cstdio>
#include <filesystem>
#include <ostream>

#include "common/trajectory/frame_reader.h"
#include "common/error.h"
#include "common/output_file.h"
#include "common/tsv.h"

namespace coolgas {

namespace {

Provenance provenance(const Trajectory& traj, const SnapshotToolOptions& o, const Frame& f) {
  Provenance p = traj.provenance();
  p.emplace_back("time", format_number(o.times.front()));
  p.emplace_back("dump_time", format_number(f.time));
  const SnapshotView v = o.scene.view;
  p.emplace_back("view", v == SnapshotView::kSlab ? "slab" : (v == SnapshotView::k3d ? "3d" : "plane"));
  if (o.scene.view == SnapshotView::kSlab) p.emplace_back("thickness", format_number(o.scene.thickness));
  if (o.scene.view == SnapshotView::k3d) p.emplace_back("max_points", std::to_string(o.scene.max_points));
  p.emplace_back("colored", std::to_string(o.scene.colored));
  p.emplace_back("output", o.output);
  return p;
}

ClusterGrid cluster_grid(const SnapshotToolOptions& o, const Frame& frame, int dimension) {
  try {
    return ClusterGrid(frame.L, dimension);
  } catch (const InputError& e) {
    throw InputError(o.input + ": " + e.what());
  }
}

std::string title(const SnapshotToolOptions& o, const Frame& f) {
  char time[32];
  std::snprintf(time, sizeof time, "%.4g", f.time);
  std::string t = std::filesystem::path(o.input).filename().string() + "   t = " + time;
  if (o.scene.view == SnapshotView::kSlab) t += "   slab |z - L/2| < " + format_number(0.5 * o.scene.thickness);
  return t;
}

// A 2D file is drawn whole in its plane: the 3D views and the slab's
// thickness do not apply to it.
SnapshotToolOptions for_dimension(const SnapshotToolOptions& o, const Trajectory& traj) {
  if (traj.dimension() == 3) return o;
  if (!o.only_3d.empty())
    throw InputError(o.input + ": " + o.only_3d + " is for 3D trajectories; this one is " +
                     std::to_string(traj.dimension()) + "D (disks), drawn whole in its plane without --view or --thickness");
  SnapshotToolOptions plane = o;
  plane.scene.view = SnapshotView::kPlane;
  return plane;
}

}  // namespace

void run_snapshot(const SnapshotToolOptions& o, std::ostream& os) {
  if (o.size_px < 100 || o.size_px > 10000)
    throw InputError("--size must be between 100 and 10000 pixels, got " + std::to_string(o.size_px));
  if (o.times.size() != 1)
    throw InputError("coolgas-snapshot draws one dump: give one --time, not " + std::to_string(o.times.size()));
  const PictureFormat format = picture_format(o.output);
  check_output_file(o.output, o.force);
  const Trajectory traj(o.input, kPosition | kAnyDimension);
  const SnapshotToolOptions opt = for_dimension(o, traj);
  Frame frame;
  traj.read(traj.dump_at(opt.times.front(), opt.exact_time), frame);
  const SnapshotScene scene =
      traj.aggregates() ? make_aggregate_scene(frame.L, frame.position, frame.mass, frame.id, opt.scene)
                        : make_scene(cluster_grid(opt, frame, traj.dimension()), frame.position, opt.scene);
  const PlotOptions plot{.title = title(opt, frame),
                         .L = frame.L,
                         .view = opt.scene.view,
                         .size_px = o.size_px,
                         .what = traj.aggregates() ? "aggregate" : "cluster",
                         .gnuplot = o.gnuplot,
                         .format = format};
  render_picture(scene, plot, o.output);
  TsvWriter out(os, "coolgas-snapshot", provenance(traj, opt, frame), {"rank", "mass", "fraction", "shown", "rgb"});
  for (const auto& c : scene.clusters)
    out.row(
        {double(c.rank), double(c.mass), double(c.mass) / double(traj.particles()), double(c.shown), double(c.rgb)});
}

}  // namespace coolgas
