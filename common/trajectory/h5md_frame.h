// One frame of an H5MD 1.1 file written by any program (de Buyl et al.,
// Comput. Phys. Commun. 185, 1546 (2014); nongnu.org/h5md/h5md.html):
// particles/<group>/position and its box/edges, with velocity, mass,
// diameter and id when the file has them. This is what a run can start
// from when the file is not a coolgas trajectory (coolgas files are read
// with frame_reader.h, which knows their completion marker).
//
// An element either varies in time (a group of value, time, step) or not
// (a plain dataset); both are read. Lengths are taken as they are: the
// file's `unit` attribute is reported, never converted (coolgas has reduced
// units, in particle diameters).
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace coolgas {

struct H5mdFrame {
  std::string group;           // the particle group read
  std::size_t frames = 0;      // frames of its position (1 when it does not vary in time)
  std::size_t index = 0;       // the frame read
  std::optional<double> time;  // its time, when position has a time
  std::vector<double> times;   // every frame's time (empty when position has none)
  int dimension = 3;           // box/dimension: 3, or 2 (disks) or 1 (rods)
  double L = 0;                // the box side (cubic or square boxes only)
  std::vector<double> position, velocity;  // 3 per particle (z = 0 for disks, y = z = 0 for rods);
                                           // velocity empty when absent
  std::vector<double> mass, diameter;      // 1 per particle; empty when absent
  std::vector<double> id;                  // 1 per particle present; empty when absent
  std::string length_unit;                 // position's `unit` attribute, "" when absent
};

// The frame nearest `time` (the earlier one on a tie), or the last. The
// group is "all" when there is one, else the only group. Particles whose id
// is -1 (H5MD's mark of an absent particle) are left out. Throws InputError
// naming the file and what is wrong: not HDF5, no /h5md or /particles,
// several groups, a missing or misshapen element (rows of d numbers in a
// box of dimension d), a box whose edges differ, not periodic, or of a
// dimension other than 1, 2 or 3. A frame of more particles than 32-bit ids
// count (2^31 - 1), or whose arrays, with `extra_bytes_per_particle` that
// the caller will need for each (a start: its engine's), exceed the memory
// available (usable_memory_bytes, common/memory.h), is refused naming the
// position dataset, its shape and the bytes, before anything is read.
H5mdFrame read_h5md_frame(const std::string& path, std::optional<double> time, double extra_bytes_per_particle = 0);
// Frame `index` (0-based; InputError naming the frames there are when it is beyond them).
H5mdFrame read_h5md_frame_at(const std::string& path, std::size_t index);

}  // namespace coolgas
