// Synthetic trajectories for the energy tests: files written by the real
// H5MD writer (common/trajectory/h5md_writer.h) holding only /parameters and the
// observables, with a kinetic energy chosen by the test.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "common/trajectory/h5md_writer.h"

namespace coolgas::test {

inline RunParameters paper_parameters(double L, std::int64_t seed) {
  RunParameters p;
  p.seed = seed;
  p.scene_toml = "[system]\nL = " + std::to_string(L) + "\nseed = " + std::to_string(seed) + "\n";
  p.N = 1000;
  p.L = L;
  p.phi = 0.208;
  p.T0 = 0.01;
  p.model = "inelastic";
  p.collision["r0"] = 0.1;
  p.collision["delta"] = 1e-4;
  return p;
}

// Writes E(t) = energy(t) at the given times (increasing) into a new file
// of a run in the geometry g.
inline void write_energy_run(const std::string& path, const RunParameters& p, const std::vector<double>& times,
                             const std::function<double(double)>& energy, Geometry g) {
  H5mdWriter w = H5mdWriter::create(path, p, true, g);
  for (double t : times) w.add_observables({t, 0, 0, energy(t), {0, 0, 0}});
  w.flush();
}

}  // namespace coolgas::test
