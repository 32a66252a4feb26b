#include "analyze/fields/tool.h"

#include <cmath>
#include <filesystem>
#include <ostream>
#include <sstream>

#include "analyze/fields/fields_table.h"
#include "analyze/fields/vti_file.h"
#include "common/error.h"
#include "common/memory.h"
#include "common/trajectory/frame_reader.h"
#include "common/tsv.h"

namespace coolgas {

int field_cells(double L, double cell, Geometry g, double memory_bytes) {
  if (!(std::isfinite(cell) && cell >= 1))
    throw InputError("--cell = " + format_number(cell) + " is out of range: the cell side must be at least one diameter");
  const int n = 2 * int(std::floor(L / cell / 2));
  if (n < 4)
    throw InputError("--cell = " + format_number(cell) + " leaves " + std::to_string(n) + " cells along the box side L = " +
                     format_number(L) + "; need at least 4: use --cell <= " + format_number(L / 4));
  const double bytes = g.power(n) * kFieldBytesPerCell;
  if (bytes > memory_bytes)
    throw InputError("--cell = " + format_number(cell) + " means " + std::to_string(n) + " cells along the box side, " +
                     bytes_text(bytes) + " of fields; this machine has " + bytes_text(memory_bytes) +
                     " to spare: use a larger --cell");
  return n;
}

namespace {

Provenance provenance(const Trajectory& traj, const FieldsOptions& o, int n, double L) {
  Provenance p = traj.provenance();
  p.emplace_back("table", o.spectrum ? "flow spectrum" : o.slab ? "slab" : "flow energies");
  if (o.slab) p.emplace_back("slab", traj.geometry().d() == 3 ? "the cells of plane iz = n/2, z from " +
                                                                  format_number(n / 2 * L / n) + " to " +
                                                                  format_number((n / 2 + 1) * L / n) + " sigma"
                                                            : "the cells of the plane");
  p.emplace_back("cells", std::to_string(n) + " per side, side " + format_number(L / n) + " sigma");
  p.emplace_back("assignment", "nearest grid point: each particle in the cell holding its centre; no smoothing");
  p.emplace_back("frame", "velocities relative to the centre of mass");
  p.emplace_back("split", "momentum field j of uniform density M/cells; j_L = (k.j) k/k^2, j_T = j - j_L (Brito & Ernst 1998)");
  p.emplace_back("noise", "independent velocities at T: E_flow (d/2) T (occupied - 1)/M; E_L T cells (M - sum M_c^2/M)/(2 M^2), E_T (d - 1) times it");
  if (traj.aggregates()) p.emplace_back("masses", "aggregates weighted by their masses");
  if (!o.vti.empty()) p.emplace_back("vti", "one VTK ImageData file a dump in the --vti directory");
  for (double t : o.times) p.emplace_back("time", format_number(t));
  return p;
}

std::string vti_path(const std::string& dir, std::size_t dump) {
  return (std::filesystem::path(dir) / ("fields_" + std::to_string(dump) + ".vti")).string();
}

}  // namespace

void run_fields(const FieldsOptions& opt, std::ostream& final_out) {
  Trajectory traj(opt.input, kPosition | kVelocity | kAnyDimension);
  const std::vector<std::size_t> dumps = traj.dumps_nearest(opt.times, opt.exact_time);
  if (dumps.empty()) throw InputError(opt.input + ": the trajectory holds no dumps");
  if (!opt.vti.empty() && !std::filesystem::is_directory(opt.vti))
    throw InputError("--vti " + opt.vti + " is not a directory; create it first");
  const Geometry g = traj.geometry();
  if (opt.slab && opt.spectrum) throw InputError("--slab and --spectrum exclude each other: choose one table");
  if (opt.slab && g.d() == 1) throw InputError("--slab draws a plane of cells; a 1D file (rods) has none");
  const FieldsTable table = opt.spectrum ? FieldsTable::kSpectrum : opt.slab ? FieldsTable::kSlab : FieldsTable::kSeries;
  const double L = traj.box_side(dumps.front());
  const int n = field_cells(L, opt.cell, g, usable_memory_bytes());
  std::ostringstream os;  // written only when every dump has been read
  TsvWriter out(os, "coolgas-fields", provenance(traj, opt, n, L), fields_columns(table));
  FourierGrid grid(n, g);
  Frame buffer;
  traj.for_each_dump(dumps, buffer, [&](const Frame& frame) {
    const std::span<const double> masses = traj.aggregates() ? std::span<const double>(frame.mass) : std::span<const double>();
    // The cells once, for the table and the .vti file.
    const CellFields f = cell_fields(n, g, frame.L, frame.position, frame.velocity, masses);
    const TableBlock b = fields_block(table, grid, frame.time, f);
    if (table == FieldsTable::kSeries) out.append(b);  // a row per dump, not a block
    else out.write(b);
    if (!opt.vti.empty()) write_vti(vti_path(opt.vti, frame.dump), f);
  });
  final_out << os.str();
}

}  // namespace coolgas
