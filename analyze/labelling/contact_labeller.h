// Clusters of particles in contact, the definition that does not percolate
// at the paper's density (issue 55): two particles are bonded when their
// centres are closer than cutoff * sigma_ij by the periodic minimum image
// (sigma_ij = (sigma_i + sigma_j)/2, their contact distance: 1 for the gas's
// unit particles, a mixture's pair's own otherwise); bonded particles belong
// to one cluster; a cluster's mass is its number of particles.
//
// The bonds are found by the shared cell list (common/close_pairs.h,
// PairsWithin) and joined by a union-find over the particles in its cell
// order (a root is linked under the smaller one; paths are halved on the way
// up); each cluster is then named by its smallest particle index, so
// clusters come out in that order: deterministic, as the unit-cell
// labeller's come in the order of their smallest cells.
// Memory: 12 bytes per particle (parent, and two arrays while naming the
// roots) besides the cell list's 32.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "common/geometry.h"

namespace coolgas {

class ContactLabeller {
 public:
  // Labels the particles at `positions` (x0 y0 z0 x1 ...; inside [0, L), the
  // coordinates past the dimension 0) of diameters `diameter` (one each;
  // empty: all 1), bonding those closer than `cutoff` times their contact
  // distance (the caller has checked 0 < cutoff * the largest diameter <= L/2).
  void label(double L, std::span<const double> positions, double cutoff, Geometry g,
             std::span<const double> diameter = {});

  // Calls f(mass) once per cluster, in the order of their smallest particles.
  template <class F>
  void for_each_mass(F&& f) const {
    for (std::int32_t r : roots_) f(std::int64_t(mass_[std::size_t(r)]));
  }
  std::size_t clusters() const { return roots_.size(); }
  // The cluster of particle i: the smallest particle index in it.
  std::int32_t root_of(std::size_t i) const { return parent_[i]; }  // flat after label()

 private:
  std::int32_t find(std::int32_t x);
  void unite(std::int32_t a, std::int32_t b);

  std::vector<std::int32_t> parent_, mass_, roots_;
};

}  // namespace coolgas
