// Clusters of the paper (Pathak et al. 2014, Sec. IV): a cell of the unit grid
// (cluster_grid.h) is occupied when it holds a particle centre; occupied cells
// sharing a face belong to one cluster, across the periodic boundaries; a
// cluster's mass is its number of particles.
//
// Labelling is a disjoint-set union whose elements are the runs of occupied
// cells along x (cluster_runs.h), joined at the contacts found by
// walk_plane_contacts() (cluster_contacts.h). It goes plane by plane as the
// occupancy grid fills (cluster_occupancy.h), so each plane is handled while it
// is in cache. The union is Rem's algorithm with splicing, the fastest
// variant in the comparison of Patwary, Blair & Manne ("Experiments on
// union-find algorithms for the disjoint-set data structure", SEA 2010), and
// 1.5x faster here than union by size with path halving. Its invariant
// parent[r] <= r makes every cluster's root its lowest-numbered run, i.e. the
// run holding its smallest cell, so one pass in increasing order flattens all
// trees and sums the masses into the roots.
// Memory: 2 bits per cell (occupancy, run starts), 4 bytes per 64 cells
// (run counts), 8 bytes per run (parent, mass) and 8 bytes per particle (the
// sort by plane).
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "analyze/labelling/cluster_runs.h"

namespace coolgas {

// One cluster, for callers that need a stable identity (ranked()).
struct Cluster {
  std::int64_t mass = 0;        // number of particles
  std::int64_t first_cell = 0;  // smallest flat cell index i + n*(j + n*k) in the cluster
  std::int32_t id = 0;          // what cluster_of() returns for its cells
};

class ClusterLabeller {
 public:
  // Labels the clusters of the particles whose centres are `positions`
  // (x0 y0 z0 x1 ..., 3N finite numbers). Buffers are kept between calls.
  void label(const ClusterGrid& grid, std::span<const double> positions);

  // Calls f(mass) once per cluster, in the order of their smallest cells.
  template <class F>
  void for_each_mass(F&& f) const {
    for (std::int32_t r : roots_) f(std::int64_t(mass_[r]));
  }
  std::size_t clusters() const { return roots_.size(); }

  // All clusters in a deterministic order: mass descending, ties by the
  // smallest cell index (as freud orders its clusters). O(runs + K log K).
  std::vector<Cluster> ranked() const;

  // Identity of the cluster holding flat cell c = i + n*(j + n*k), or -1 if c is empty.
  std::int32_t cluster_of(std::int64_t c) const;

 private:
  void add_plane(int k);
  void unite(std::int32_t a, std::int32_t b);
  void flatten();

  CellOccupancy occ_;
  CellRuns runs_;
  std::vector<std::int32_t> parent_;  // parent run; a root is its own parent
  std::vector<std::int32_t> mass_;    // particles in the run; after flatten(), in the cluster at roots
  std::vector<std::int32_t> roots_;   // root runs in increasing order
};

}  // namespace coolgas
