// LAMMPS text dumps (docs.lammps.org/dump.html), as read by LAMMPS's
// read_dump, OVITO and MDAnalysis (format LAMMPSDUMP):
//
//   ITEM: TIMESTEP
//   <the dump's collision count>
//   ITEM: NUMBER OF ATOMS
//   3000
//   ITEM: BOX BOUNDS pp pp pp
//   0 25
//   0 25
//   0 25
//   ITEM: ATOMS id type x y z vx vy vz ix iy iz
//   1 1 1.25 3.5 0.75 -0.1 0.2 0.3 0 0 -1
//
// radius and mass follow for ballistic aggregates. ids are coolgas ids + 1
// (LAMMPS ids are positive), every particle has type 1, x y z are wrapped
// into [0, L) and ix iy iz are the image counts. The format has no comment
// line and no time (TIMESTEP is an integer; MDAnalysis 2.4 also reads
// exactly nine header lines per frame, so no ITEM: TIME is written).
// A 2D frame (disks) has z = vz = iz = 0 and z bounds -0.5 0.5, as a LAMMPS
// run with `dimension 2` has them (its z must straddle 0): read_dump into such
// a run, or OVITO, reads the plane.
#pragma once
#include <iosfwd>

#include "common/trajectory/frame_reader.h"
#include "common/geometry.h"

namespace coolgas {

// `frame` as read by a Trajectory opened for position, velocity and image
// (and diameter, for aggregation files).
void write_lammps_frame(std::ostream& out, const Frame& frame, Geometry g);

}  // namespace coolgas
