// Extended XYZ frames (the format of ASE, OVITO and QUIP; VMD reads the
// plain XYZ part): a line with the number of particles, a comment line of
// key=value pairs, then one line per particle. coolgas writes
//
//   3000
//   Lattice="25 0 0 0 25 0 0 0 25" Properties=species:S:1:pos:R:3:velo:R:3:id:I:1 pbc="T T T" Time=10 ...
//   X 1.25 3.5 0.75 -0.1 0.2 0.3 0
//
// with omega:R:3 after velo for a rough run's angular velocities (disks: about
// z), and radius:R:1:mass:R:1 appended for ballistic aggregates (a 2D frame,
// disks: Lattice="L 0 0 0 L 0 0 0 1" pbc="T T F", z = 0: periodic in the
// plane, as ASE and OVITO read a 2D system; a 1D frame, rods:
// Lattice="L 0 0 0 1 0 0 0 1" pbc="T F F", y = z = 0), every number in
// its shortest form that reads back to the same double (so a frame written
// and read again is exact), and the provenance as further quoted pairs.
// Reading takes what another program may write: any order of properties, pos
// and velo (or vel, velocities), omega (or angular_velocity), radius or
// diameter, mass (or masses), the other columns skipped; a missing Properties is species:S:1:pos:R:3.
#pragma once
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "common/tsv.h"

namespace coolgas {

struct XyzFrame {
  double L = 0;                // periodic box side: a cube, a square (2D) or a ring (1D)
  int dimension = 3;           // 2 for disks, 1 for rods (see above); read from pbc=
  std::optional<double> time;  // Time=
  std::optional<std::int64_t> step;
  std::optional<double> T0;    // T0= (coolgas-convert writes the source's time unit); read only
  std::vector<double> position, velocity;  // 3 per particle; velocity empty when absent
  std::vector<double> diameter, mass;      // 1 per particle; empty when absent (written as radius = d/2)
  std::vector<std::int64_t> id;            // written when given; not read
  std::vector<double> angular_velocity;    // 3 per particle (omega:R:3); empty when absent
};

// Writes one frame; `provenance` pairs follow Time= as key="value" (keys made
// of letters, digits and _ ; quotes in values become ').
void write_xyz_frame(std::ostream& out, const XyzFrame& frame, const Provenance& provenance);

// Reads the frame nearest `time` by its Time= (the earlier on a tie), or the
// last frame. Throws InputError naming `source`, the line and what was wrong:
// not an extended XYZ file (no count, no Lattice), a Lattice that is not a
// cube (a square for pbc="T T F"), pbc not "T T T", "T T F" or "T F F", a
// disk or rod off the first one's plane or line or moving across it (whose
// coordinates there are then set to 0), missing positions, a short or unreadable line,
// `time` asked for but a frame without Time=, a Time= that is not finite and
// >= 0, a T0= that is not finite and > 0, a count line claiming more particles
// than the rest of the stream (when it can seek) or the memory available can
// hold (checked before anything is allocated).
XyzFrame read_xyz_frame(std::istream& in, const std::string& source, std::optional<double> time);

}  // namespace coolgas
