// The shape of every cluster of one frame.
//
// Gas: the paper's clusters (analyze/labelling/cluster_labeller.h), each
// unwrapped along its own connectivity (unwrapping.h); the gyration tensor is
// that of its particles' centres, each of unit mass.
// Ballistic aggregation: the file records each aggregate's mass and centre,
// not where its particles are, so an aggregate's shape is that of the solid
// sphere it is in the simulation: diameter d = m^(1/3) (volumes add), all
// three eigenvalues d^2/20, R_g^2 = (3/5)(d/2)^2, asphericity and
// prolateness 0, and M ~ R_g^3 exactly; in 2D the solid disc of diameter
// m^(1/2) (areas add): both eigenvalues d^2/16, M ~ R_g^2; in 1D the solid
// rod of length m (lengths add): its one eigenvalue m^2/12, M ~ R_g.
#pragma once
#include <span>
#include <vector>

#include "analyze/labelling/cluster_grid.h"
#include "analyze/labelling/cluster_labeller.h"
#include "analyze/shape/gyration.h"
#include "analyze/shape/unwrapping.h"

namespace coolgas {

struct ClusterShape {
  Shape shape;
  bool wraps = false;  // winds around the periodic box: no shape of its own (unwrapping.h)
};

class ClusterShapes {
 public:
  // The clusters of particles at `positions` (x0 y0 z0 x1 ...), in the
  // labeller's ranked() order (mass descending, ties by smallest cell).
  std::vector<ClusterShape> of_particles(const ClusterGrid& grid, std::span<const double> positions);

 private:
  ClusterLabeller labeller_;
  ClusterUnwrapping unwrapping_;
  std::vector<GyrationSums> sums_;
};

// Aggregates of masses `mass` as solid spheres (2D: discs, 1D: rods), in order of decreasing mass (stable).
std::vector<ClusterShape> aggregate_shapes(std::span<const double> mass, Geometry g);

}  // namespace coolgas
