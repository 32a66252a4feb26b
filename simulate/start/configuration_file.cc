#include "simulate/start/configuration_file.h"

#include <hdf5.h>

#include <filesystem>
#include <fstream>

#include "common/error.h"
#include "common/extended_xyz.h"
#include "common/hdf5_file.h"
#include "common/trajectory/frame_reader.h"
#include "common/trajectory/h5md_frame.h"
#include "common/trajectory/layout.h"
#include "common/trajectory/run_info.h"
#include "simulate/scene/scene.h"

namespace coolgas {

namespace {

bool is_coolgas_trajectory(const std::string& path) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  return layout::is_coolgas(f.id());
}

FileConfiguration from_coolgas(const std::string& path, std::optional<double> time) {
  const Trajectory t(path, kPosition | kVelocity | kDiameter | kAngularVelocity | kAnyDimension);
  Frame f;
  t.read(time ? t.nearest_dump(*time) : t.dump_times().size() - 1, f);
  FileConfiguration c{"coolgas trajectory", t.dimension(), f.L, f.time, std::move(f.position), std::move(f.velocity),
                      std::move(f.diameter), std::move(f.mass), read_run_info(path).params.T0, "",
                      std::move(f.angular_velocity)};
  return c;
}

FileConfiguration from_h5md(const std::string& path, std::optional<double> time) {
  // The frame's particles are refused before reading when they and the
  // engine they become would not fit (scene.h: the engine's bytes a particle).
  H5mdFrame f = read_h5md_frame(path, time, kBytesPerParticle);
  return {"H5MD 1.1 (group '" + f.group + "')", f.dimension, f.L, f.time, std::move(f.position), std::move(f.velocity),
          std::move(f.diameter), std::move(f.mass), std::nullopt, f.length_unit};
}

FileConfiguration from_xyz(const std::string& path, std::optional<double> time) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read '" + path + "'");
  XyzFrame f = read_xyz_frame(in, path, time);
  return {"extended XYZ", f.dimension, f.L,       f.time, std::move(f.position), std::move(f.velocity),
          std::move(f.diameter), std::move(f.mass), f.T0, "",     std::move(f.angular_velocity)};
}

}  // namespace

FileConfiguration read_configuration(const std::string& path, std::optional<double> time) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError("cannot read '" + path + "': no such file");
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError("cannot read '" + path + "': not a regular file (a directory or a device)");
  h5::silence_library_errors();
  if (H5Fis_hdf5(path.c_str()) > 0) return is_coolgas_trajectory(path) ? from_coolgas(path, time) : from_h5md(path, time);
  return from_xyz(path, time);
}

}  // namespace coolgas
