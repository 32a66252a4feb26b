#include "analyze/snapshot/tool.h"

#include <cstdio>
#include <filesystem>
#include <ostream>

#include "analyze/snapshot/space_time.h"
#include "common/trajectory/frame_reader.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/memory.h"
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
    return ClusterGrid(frame.L, Geometry(dimension));
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

// A 1D file: every option of the 2D and 3D pictures is refused, naming the first given.
void refuse_for_rods(const SnapshotToolOptions& o) {
  const std::string given = o.only_3d.empty() ? o.not_1d : o.only_3d;
  if (given.empty()) return;
  throw InputError(o.input + ": " + given + " is not for 1D trajectories (rods): a 1D file is drawn as a space-time " +
                   "diagram of its dumps up to --time, coloured by velocity, without --view, --thickness, --colored " +
                   "or --max-points");
}

struct RodDumps {
  double L = 0;  // the ring's length at the last dump
  std::vector<SpaceTimeRow> rows;
};

// The rows are held until gnuplot runs: refused before reading when they
// would not fit the memory available.
void check_rows_fit(const Trajectory& traj, std::size_t last) {
  const double bytes = double(last + 1) * double(traj.particles()) * sizeof(SpaceTimeRod);
  const double memory = usable_memory_bytes();
  if (bytes > memory)
    throw InputError(traj.path() + ": " + std::to_string(last + 1) + " dumps of " + std::to_string(traj.particles()) +
                     " rods take " + bytes_text(bytes) + ", more than the memory available (" + bytes_text(memory) +
                     "); give an earlier --time");
}

RodDumps read_rod_dumps(const std::string& path, std::size_t last) {
  const Trajectory traj(path, kPosition | kVelocity | kAnyDimension);
  check_rows_fit(traj, last);
  RodDumps dumps;
  Frame f;
  for (std::size_t d = 0; d <= last; ++d) {
    if (interrupted())
      throw Interrupted(interrupt_signal(), "after " + std::to_string(d) + " of " + std::to_string(last + 1) +
                                                " dumps; no picture or table written");
    traj.read(d, f);
    dumps.rows.push_back(space_time_row(f.time, f.position, f.velocity,
                                        traj.aggregates() ? std::span<const double>(f.mass) : std::span<const double>()));
    dumps.L = f.L;
  }
  return dumps;
}

Provenance space_time_provenance(const Trajectory& traj, const SnapshotToolOptions& o, const RodDumps& dumps) {
  Provenance p = traj.provenance();
  p.emplace_back("time", format_number(o.times.front()));
  p.emplace_back("dump_time", format_number(dumps.rows.back().t));
  p.emplace_back("view", "space-time");
  p.emplace_back("rows", std::to_string(dumps.rows.size()) + " dumps, the first to the one nearest --time");
  p.emplace_back("colour", "v / v_rms of each dump, blue -" + format_number(kSpaceTimeVelocityRange) + " .. grey 0 .. red +" +
                               format_number(kSpaceTimeVelocityRange));
  p.emplace_back("output", o.output);
  return p;
}

void draw_space_time(const SnapshotToolOptions& o, const Trajectory& traj, PictureFormat format, std::ostream& os) {
  refuse_for_rods(o);
  const RodDumps dumps = read_rod_dumps(o.input, traj.dump_at(o.times.front(), o.exact_time));
  char last[32];
  std::snprintf(last, sizeof last, "%.4g", dumps.rows.back().t);
  const PlotOptions plot{.title = std::filesystem::path(o.input).filename().string() + "   space-time, t up to " + last,
                         .L = dumps.L,
                         .size_px = o.size_px,
                         .what = traj.aggregates() ? "aggregate" : "rod",
                         .gnuplot = o.gnuplot,
                         .format = format};
  render_space_time(dumps.rows, plot, o.output);
  TsvWriter out(os, "coolgas-snapshot", space_time_provenance(traj, o, dumps), {"t", "particles", "v_rms"});
  for (const SpaceTimeRow& r : dumps.rows) out.row({r.t, double(r.rods.size()), r.v_rms});
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
  if (traj.dimension() == 1) return draw_space_time(o, traj, format, os);
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
