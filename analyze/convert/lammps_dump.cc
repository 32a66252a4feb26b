#include "analyze/convert/lammps_dump.h"

#include <ostream>

#include "common/tsv.h"

namespace coolgas {

void write_lammps_frame(std::ostream& out, const Frame& f, Geometry g) {
  const std::size_t n = f.particles();
  const bool aggregates = !f.id.empty();
  const std::string L = format_number(f.L);
  out << "ITEM: TIMESTEP\n" << f.step << "\nITEM: NUMBER OF ATOMS\n" << n << "\nITEM: BOX BOUNDS pp pp pp\n";
  for (int d = 0; d < 3; ++d) out << (g.spans(d) ? "0 " + L : std::string("-0.5 0.5")) << "\n";
  const bool spins = !f.angular_velocity.empty();  // a rough run's (LAMMPS's sphere style names them so)
  out << "ITEM: ATOMS id type x y z vx vy vz ix iy iz" << (spins ? " omegax omegay omegaz" : "")
      << (aggregates ? " radius mass" : "") << "\n";
  for (std::size_t i = 0; i < n; ++i) {
    out << (aggregates ? std::int64_t(f.id[i]) : std::int64_t(i)) + 1 << " 1";
    for (int d = 0; d < 3; ++d) out << " " << format_number(f.position[3 * i + d]);
    for (int d = 0; d < 3; ++d) out << " " << format_number(f.velocity[3 * i + d]);
    for (int d = 0; d < 3; ++d) out << " " << f.image[3 * i + d];
    if (spins)
      for (int d = 0; d < 3; ++d) out << " " << format_number(f.angular_velocity[3 * i + d]);
    if (aggregates) out << " " << format_number(f.diameter[i] / 2) << " " << format_number(f.mass[i]);
    out << "\n";
  }
}

}  // namespace coolgas
