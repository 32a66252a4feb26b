// A configuration read from a file a run can start from (system.init =
// "file"): a coolgas trajectory of any model, an H5MD 1.1 file of another
// program, or an extended XYZ file. The format is told by the content (an
// HDF5 signature, then coolgas's /parameters), never by the file name.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace coolgas {

struct FileConfiguration {
  std::string format;          // "coolgas trajectory", "H5MD 1.1 (group 'g')", "extended XYZ"
  int dimension = 3;           // 3, or 2 for disks, 1 for rods
  double L = 0;                // periodic box side (a cube, square or ring)
  std::optional<double> time;  // the frame's time, when the file has one
  std::vector<double> position, velocity;  // 3 per particle (z = 0 in 2D, y = z = 0 in 1D);
                                           // velocity empty when absent
  std::vector<double> diameter, mass;      // 1 per particle; empty when absent
  std::optional<double> T0;    // the time unit's temperature: a coolgas trajectory's /parameters/T0,
                               // an extended XYZ comment's T0= (coolgas-convert copies it there)
  std::string length_unit;     // a foreign H5MD file's unit of position, "" when none
  std::vector<double> angular_velocity;  // 3 per particle: a rough run's spins (coolgas, or XYZ omega:R:3); empty when absent
};

// The frame nearest `time` (coolgas: its dump nearest; the others by their
// own times), or the last. Throws InputError naming the file: missing, not a
// regular file, or not one of the formats (and what is wrong with it).
FileConfiguration read_configuration(const std::string& path, std::optional<double> time);

}  // namespace coolgas
