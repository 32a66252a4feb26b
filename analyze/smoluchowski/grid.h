// The state of the Smoluchowski solver and the interface every method offers.
//
// The state is a vector of number concentrations, one per grid cell. Cell i
// sits at the pivot mass mass[i] and covers the mass interval
// [edge[i], edge[i+1]), edges halfway between pivots; integer mass m covers
// [m − ½, m + ½). On the uniform grid (direct and FFT methods) cell i is the
// single mass i+1; on the geometric grid cells widen with mass (see
// geometric.h). The last pivot is the cut-off M: clusters that
// would grow beyond it leave the system, and that leaked mass is reported.
#pragma once
#include <cstdint>
#include <vector>

namespace coolgas::smoluchowski {

struct MassGrid {
  std::vector<double> mass;  // pivot mass of each cell
  std::vector<double> edge;  // cell boundaries, size() + 1 of them: ½, ..., M + ½
  std::size_t size() const { return mass.size(); }
  double width(std::size_t i) const { return edge[i + 1] - edge[i]; }
  std::int64_t cutoff() const { return static_cast<std::int64_t>(mass.back()); }
};

// Cells 1, 2, ..., M, one integer mass each.
MassGrid uniform_grid(std::int64_t M);

// dc/dt of the truncated equation in the ½-gain convention,
//   dc_k/dt = ½ Σ_{i+j=k} K(i,j) c_i c_j − c_k Σ_{j<=M} K(k,j) c_j,
// (discretised on the method's grid). Implementations may keep scratch space,
// hence non-const; the result depends on c only (deterministic). A long
// evaluation may return early, its result unfinished, once SIGINT/SIGTERM/
// SIGHUP arrived (common/interrupt.h): the integrator then stops the step.
class CoagulationRhs {
 public:
  virtual ~CoagulationRhs() = default;
  virtual const MassGrid& grid() const = 0;
  virtual void evaluate(const double* c, double* dcdt) = 0;
};

}  // namespace coolgas::smoluchowski
