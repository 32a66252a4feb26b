#include "analyze/convert/tool.h"

#include <cmath>
#include <ostream>

#include "analyze/convert/lammps_dump.h"
#include "common/error.h"
#include "common/extended_xyz.h"
#include "common/interrupt.h"
#include "common/trajectory/frame_reader.h"
#include "common/version.h"

namespace coolgas {

namespace {

XyzFrame xyz_of(const Frame& f, int dimension) {
  XyzFrame x{f.L, dimension, f.time, f.step, std::nullopt, f.position, f.velocity, f.diameter, f.mass, {}, f.angular_velocity};
  x.id.resize(f.particles());
  for (std::size_t i = 0; i < x.id.size(); ++i) x.id[i] = f.id.empty() ? std::int64_t(i) : f.id[i];
  return x;
}

// LAMMPS runs in 2 or 3 dimensions only: a 1D file has no LAMMPS dump.
void check_format(const ConvertOptions& opt, int dimension) {
  if (opt.format != ExportFormat::kLammps || dimension != 1) return;
  throw InputError(opt.input + ": a 1D trajectory (rods) has no LAMMPS dump: LAMMPS runs in 2 or 3 dimensions; use "
                   "--format xyz (pbc=\"T F F\")");
}

}  // namespace

void run_convert(const ConvertOptions& opt, std::ostream& out) {
  for (double t : opt.times)
    if (!std::isfinite(t)) throw InputError("--time " + format_number(t) + ": a time is a finite number [1/omega0]");
  const Trajectory t(opt.input, kPosition | kVelocity | kImage | kDiameter | kAngularVelocity | kAnyDimension);
  check_format(opt, t.dimension());
  const std::vector<std::size_t> dumps =
      opt.last ? std::vector<std::size_t>{t.dump_times().size() - 1} : t.dumps_nearest(opt.times, opt.exact_time);
  Provenance provenance{{"tool", "coolgas-convert"}, {"version", program_version()}};
  for (auto& p : t.provenance()) provenance.push_back(std::move(p));
  // Each frame is written whole (formatting 10^7 particles takes seconds);
  // a signal stops the stream between two frames.
  Frame f;
  for (std::size_t i = 0; i < dumps.size(); ++i) {
    if (interrupted())
      throw Interrupted(interrupt_signal(), "after " + std::to_string(i) + " of " + std::to_string(dumps.size()) +
                                                " dumps; the frames written so far are whole");
    t.read(dumps[i], f);
    if (opt.format == ExportFormat::kXyz) write_xyz_frame(out, xyz_of(f, t.dimension()), provenance);
    else write_lammps_frame(out, f, t.geometry());
  }
}

}  // namespace coolgas
