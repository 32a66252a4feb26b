#include "analyze/fields/fields_table.h"

namespace coolgas {

const std::vector<std::string>& fields_columns(FieldsTable table) {
  static const std::vector<std::string> series = {"t",      "cells",  "E",          "E_flow",     "E_thermal",
                                                  "T",      "E_flow_noise", "E_L", "E_T",   "E_L_noise",
                                                  "E_T_noise", "density_var", "vorticity2"};
  static const std::vector<std::string> shells = {"t", "shell", "k", "E_L", "E_T", "modes"};
  static const std::vector<std::string> slab = {"t", "x", "y", "density", "vorticity"};
  return table == FieldsTable::kSeries ? series : table == FieldsTable::kSpectrum ? shells : slab;
}

std::vector<double> fields_row(double t, const CellFields& f, const FieldEnergies& e, const FlowSplit& s) {
  return {t,
          double(f.n),
          e.kinetic,
          e.flow,
          e.thermal,
          e.temperature,
          e.flow_noise,
          s.longitudinal,
          s.transverse,
          s.longitudinal_noise,
          s.transverse_noise,
          e.density_variance,
          s.vorticity2};
}

TableBlock spectrum_block(double t, const FlowSplit& s) {
  TableBlock b;
  b.comment = "t = " + format_number(t);
  for (const FlowShell& sh : s.shells)
    if (sh.modes > 0) b.rows.push_back({t, double(sh.shell), sh.k, sh.longitudinal, sh.transverse, double(sh.modes)});
  return b;
}

}  // namespace coolgas

namespace coolgas {

TableBlock slab_block(double t, const CellFields& f) {
  TableBlock b;
  b.comment = "t = " + format_number(t);
  const int n = f.n, iz = f.g.spans(2) ? n / 2 : 0;
  const double h = f.cell_side(), volume = f.g.power(h);
  for (int iy = 0; iy < n; ++iy)
    for (int ix = 0; ix < n; ++ix) {
      const std::int64_t c = ix + std::int64_t(n) * (iy + std::int64_t(n) * iz);
      b.rows.push_back({t, (ix + 0.5) * h, (iy + 0.5) * h, f.count[c] / volume, cell_vorticity(f, c)[2]});
    }
  return b;
}

}  // namespace coolgas

namespace coolgas {

TableBlock fields_block(FieldsTable table, FourierGrid& grid, double t, double L, std::span<const double> positions,
                        std::span<const double> velocities, std::span<const double> masses) {
  return fields_block(table, grid, t, cell_fields(grid.n(), grid.geometry(), L, positions, velocities, masses));
}

TableBlock fields_block(FieldsTable table, FourierGrid& grid, double t, const CellFields& f) {
  if (table == FieldsTable::kSlab) return slab_block(t, f);
  const FieldEnergies e = field_energies(f);
  const FlowSplit s = flow_split(f, e.temperature, grid);
  if (table == FieldsTable::kSpectrum) return spectrum_block(t, s);
  return {"", {fields_row(t, f, e, s)}};
}

}  // namespace coolgas
