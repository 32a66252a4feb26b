// Random site percolation on the periodic simple cubic (dimension 3, L^3
// sites) or square (dimension 2, L^2) lattice: each site occupied with
// probability p, one particle at each occupied site's centre; and the
// mass-radius fit of its finite clusters from `fit_from` sites on.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "analyze/shape/cluster_shapes.h"
#include "analyze/shape/mass_radius.h"
#include "common/random.h"

namespace coolgas::test {

inline MassRadius percolation_mass_radius(int L, int dimension, double p, std::uint64_t seed, const std::string& fit_from) {
  Random rng(seed);
  std::vector<double> sites;
  const int planes = dimension == 3 ? L : 1;
  for (int k = 0; k < planes; ++k)
    for (int j = 0; j < L; ++j)
      for (int i = 0; i < L; ++i)
        if (rng.uniform() < p) sites.insert(sites.end(), {i + 0.5, j + 0.5, dimension == 3 ? k + 0.5 : 0.0});
  ClusterShapes shapes;
  MassRadius mr =
      mass_radius(shapes.of_particles(ClusterGrid(L, Geometry(dimension)), sites), 10, parse_window(fit_from, "--fit-mass"));
  std::printf("%dD percolation at p = %g: d_f = %.3f +- %.3f over %d bins\n", dimension, p, mr.d_f, mr.d_f_err,
              mr.fit_bins);
  return mr;
}

}  // namespace coolgas::test
