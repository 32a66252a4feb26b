#include "analyze/velocity/tool.h"

#include <cmath>
#include <ostream>
#include <span>
#include <sstream>

#include "common/trajectory/frame_reader.h"
#include "common/trajectory/species_selection.h"
#include "analyze/velocity/velocity_table.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tool_main.h"
#include "common/tsv.h"

namespace coolgas {

namespace {

const char* table_name(VelocityTable t) {
  switch (t) {
    case VelocityTable::kPhi:
      return "Phi";
    case VelocityTable::kTail:
      return "tail";
    case VelocityTable::kSeries:
      return "series";
  }
  return "";
}

Provenance provenance(const Trajectory& traj, const VelocityOptions& o) {
  Provenance p = traj.provenance();
  p.emplace_back("table", table_name(o.table));
  p.emplace_back("bins", std::to_string(o.bins));
  p.emplace_back("ymax", format_number(o.ymax));
  p.emplace_back("tail_from", format_number(o.tail_from));
  p.emplace_back("min_count", format_number(o.min_count));
  for (double t : o.times) p.emplace_back("time", format_number(t));
  return p;
}

std::string no_tail_text(const Trajectory& traj, const Frame& f, const VelocityOptions& o, std::size_t points) {
  return traj.path() + ": dump at t = " + format_number(f.time) + ": only " + std::to_string(points) +
         " tail bins with y >= " + format_number(o.tail_from) + " and >= " + format_number(o.min_count) +
         " samples (3 needed to fit beta)";
}

[[noreturn]] void no_tail(const Trajectory& traj, const Frame& f, const VelocityOptions& o, std::size_t points) {
  throw InputError(no_tail_text(traj, f, o, points) + "; lower --tail-from or --min-count, or use wider bins");
}

// A rough run's spins as vectors of a space of d_r dimensions, the geometry
// the statistics take them in: spheres' as they are (d_r = 3), disks' z
// components first (d_r = 1, the others 0).
Geometry spin_space(const Trajectory& traj) { return Geometry(traj.geometry().rotational_axes()); }
std::span<const double> spins_of(const Frame& f, Geometry space, std::vector<double>& packed) {
  if (space.d() == 3) return f.angular_velocity;
  packed.assign(f.angular_velocity.size(), 0.0);
  for (std::size_t i = 0; 3 * i < packed.size(); ++i) packed[3 * i] = f.angular_velocity[3 * i + 2];
  return packed;
}

}  // namespace

void run_velocity(const VelocityOptions& opt, std::ostream& final_out) {
  // The table is built in memory and written only when every dump has been
  // read: a bad dump leaves no half table behind.
  std::ostringstream os;
  check_tail_options(opt.tail_from, opt.min_count);
  ComponentHistogram hist(opt.bins, opt.ymax);
  Trajectory traj(opt.input, kVelocity | (opt.spins ? kAngularVelocity : 0u) | (opt.species ? kSpecies : 0u) |
                                 kAnyDimension);
  check_species_option(traj, opt.species);
  if (opt.spins && !traj.has(kAngularVelocity))
    throw InputError(opt.input + ": no angular velocities (its particles are smooth); --spins needs a run of rough "
                     "particles (collision.beta > -1)");
  const Geometry space = opt.spins ? spin_space(traj) : traj.geometry();
  std::vector<double> packed;
  Provenance p = provenance(traj, opt);
  if (opt.spins) p.emplace_back("of", "angular_velocity");
  if (opt.species) p.emplace_back("species", std::to_string(*opt.species));
  TsvWriter out(os, "coolgas-velocity", p, velocity_columns(opt.table));
  Frame buffer;
  std::vector<std::string> notes;  // printed once every dump is read: an error stays one line
  traj.for_each_dump(traj.dumps_nearest(opt.times, opt.exact_time), buffer, [&](const Frame& frame) {
    const VelocityStats s = [&] {
      try {
        const std::span<const double> values =
            opt.spins     ? spins_of(frame, space, packed)
            : opt.species ? species_values(frame.velocity, 3, frame.species, *opt.species, packed)
                          : frame.velocity;
        return velocity_stats(values, hist, opt.tail_from, opt.min_count, space);
      } catch (const InputError& e) {  // the dump the statistics refuse
        throw InputError(opt.input + ": dump at t = " + format_number(frame.time) + ": " + e.what());
      }
    }();
    if (opt.table == VelocityTable::kTail && !s.fit) no_tail(traj, frame, opt, s.tail.size());
    const TableBlock b = velocity_block(opt.table, frame.time, hist, s, opt.tail_from);
    if (opt.table == VelocityTable::kSeries) {
      if (!s.fit) notes.push_back(no_tail_text(traj, frame, opt, s.tail.size()) + "; beta is nan in that row");
      out.append(b);  // a row per dump, not a block
    } else {
      out.write(b);
    }
  });
  for (const std::string& text : notes) note(text);
  final_out << os.str();
}

}  // namespace coolgas
