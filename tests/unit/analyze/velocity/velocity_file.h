// The velocity tool end to end on a file from the real writer: one dump at
// t = 5 with the given velocities (3 numbers per particle; a 2D file, of
// `dimension` 2, keeps vx and vy, a 1D file vx), and coolgas-velocity's
// series table of it.
#pragma once
#include <sstream>
#include <string>
#include <vector>

#include "analyze/velocity/tool.h"
#include "common/trajectory/h5md_writer.h"
#include "common/tsv.h"

namespace coolgas::test {

inline Table velocity_series_of(const std::string& path, const std::vector<double>& vel, double L, int dimension) {
  const std::size_t n = vel.size() / 3;
  {
    RunParameters p;
    p.N = static_cast<std::int64_t>(n);
    p.L = L;
    H5mdWriter w = H5mdWriter::create(path, p, false, Geometry(dimension));
    const std::vector<double> pos(3 * n, 1.0);
    const std::vector<std::int32_t> img(3 * n, 0);
    w.add_frame({5.0, 10, 0, pos.data(), img.data(), vel.data()});
  }
  VelocityOptions o;
  o.input = path;
  o.table = VelocityTable::kSeries;
  std::stringstream out;
  run_velocity(o, out);
  return read_table(out, "out");
}

}  // namespace coolgas::test
