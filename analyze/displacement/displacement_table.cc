#include "analyze/displacement/displacement_table.h"

#include "common/error.h"

namespace coolgas {

const std::vector<std::string>& displacement_columns() {
  static const std::vector<std::string> columns{"t", "dt", "msd", "msd_err", "vacf", "vacf_norm", "T", "D_apparent"};
  return columns;
}

TableBlock displacement_row(const DisplacementOrigin& origin, double t_ref, double L_ref, double t, double L,
                            std::span<const double> positions, std::span<const std::int32_t> images,
                            std::span<const double> velocities) {
  const std::size_t n = positions.size() / 3;
  if (n != origin.particles() || images.size() != positions.size() || velocities.size() != positions.size())
    throw InputError("the dump at t = " + format_number(t) + " holds " + std::to_string(n) +
                     " particles, the reference dump " + std::to_string(origin.particles()) +
                     ": displacements need the same particles");
  if (L != L_ref)
    throw InputError("the box side at t = " + format_number(t) + " is " + format_number(L) + ", at the reference " +
                     format_number(L_ref) + ": displacements need one box");
  const Displacement d = origin.from_here(L, positions, images, velocities);
  const double dt = t - t_ref;
  TableBlock b;
  b.rows.push_back({t, dt, d.msd, d.msd_err, d.vacf, d.vacf_norm, d.T, d.D_apparent(dt)});
  return b;
}

}  // namespace coolgas
