#include "analyze/displacement/tool.h"

#include <ostream>
#include <sstream>

#include "analyze/displacement/displacement_table.h"
#include "common/error.h"
#include "common/trajectory/frame_reader.h"
#include "common/tsv.h"

namespace coolgas {

namespace {

Provenance provenance(const Trajectory& traj, const DisplacementOptions& o, double t_ref) {
  Provenance p = traj.provenance();
  p.emplace_back("reference", "t_ref = " + format_number(t_ref) + (o.from ? " (--from)" : " (the first dump)"));
  p.emplace_back("unwrapping", "position + L image, the image counts of the dumps: exact at any dump spacing");
  p.emplace_back("averages", "over the particles, from the one reference dump (no average over time origins)");
  for (double t : o.times) p.emplace_back("time", format_number(t));
  return p;
}

// The rows' dumps: those nearest --time, or every dump from the reference on.
std::vector<std::size_t> row_dumps(const Trajectory& traj, const DisplacementOptions& o, std::size_t ref) {
  if (!o.times.empty()) return traj.dumps_nearest(o.times, o.exact_time);
  std::vector<std::size_t> dumps;
  for (std::size_t i = ref; i < traj.dump_times().size(); ++i) dumps.push_back(i);
  return dumps;
}

}  // namespace

void run_displacement(const DisplacementOptions& opt, std::ostream& final_out) {
  Trajectory traj(opt.input, kPosition | kVelocity | kImage | kAnyDimension);
  if (traj.aggregates())
    throw InputError(opt.input + " is a ballistic-aggregation file: its aggregates merge, and displacements need "
                     "particles that keep their identity");
  if (traj.dump_times().empty()) throw InputError(opt.input + ": the trajectory holds no dumps");
  const std::size_t ref = opt.from ? traj.dump_at(*opt.from, opt.exact_time) : 0;
  Frame reference;
  traj.read(ref, reference);
  const DisplacementOrigin origin(reference.L, reference.position, reference.image, reference.velocity, traj.geometry());
  std::ostringstream os;  // written only when every dump has been read
  TsvWriter out(os, "coolgas-displacement", provenance(traj, opt, reference.time), displacement_columns());
  Frame buffer;
  traj.for_each_dump(row_dumps(traj, opt, ref), buffer, [&](const Frame& f) {
    try {
      out.append(displacement_row(origin, reference.time, reference.L, f.time, f.L, f.position, f.image, f.velocity));
    } catch (const InputError& e) {
      throw InputError(opt.input + ": " + e.what());
    }
  });
  final_out << os.str();
}

}  // namespace coolgas
