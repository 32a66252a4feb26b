// A small gas trajectory for the CLI tests of the analysis tools: N = 3000
// uniformly placed particles in a box of side 25 with Gaussian velocities,
// two dumps (t = 0 and 10), seed 9 of the portable generator; optionally a
// NaN at one position or one velocity of the second dump.
#pragma once
#include <limits>
#include <string>
#include <vector>

#include "common/random.h"
#include "common/trajectory/h5md_writer.h"

namespace coolgas::test {

// (n, L: a larger gas of the same kind, for tests that need long work.)
inline void write_gas_file(const std::string& path, bool nan_at_position = false, bool nan_at_velocity = false,
                           std::int64_t n = 3000, double L = 25) {
  RunParameters p;
  p.N = n;
  p.L = L;
  p.seed = 9;
  H5mdWriter w = H5mdWriter::create(path, p, true, Geometry(3));
  Random rng(9);
  std::vector<double> pos(3 * n), vel(3 * n);
  std::vector<std::int32_t> img(3 * n, 0);
  for (int f = 0; f < 2; ++f) {
    for (double& x : pos) x = p.L * rng.uniform();
    for (double& v : vel) v = rng.normal();
    if (f == 1 && nan_at_position) pos[3 * 17 + 1] = std::numeric_limits<double>::quiet_NaN();
    if (f == 1 && nan_at_velocity) vel[3 * 5] = std::numeric_limits<double>::quiet_NaN();
    w.add_frame({double(10 * f), 100 * f, 0, pos.data(), img.data(), vel.data()});
  }
}

}  // namespace coolgas::test
