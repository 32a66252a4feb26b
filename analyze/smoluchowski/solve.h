// One call from an initial distribution to a final one: what tests, the
// benchmark and the accuracy study need (the tool's driver adds output times).
#pragma once
#include <vector>

#include "analyze/smoluchowski/integrator.h"
#include "analyze/smoluchowski/kernel.h"
#include "analyze/smoluchowski/method.h"

namespace coolgas::smoluchowski {

struct Solution {
  MassGrid grid;
  std::vector<double> c;  // concentrations per cell at time t
  double t = 0;           // ½-gain time
  long steps = 0, evaluations = 0;
};

// Integrates from c0 (indexed by integer mass, see initial_masses) to t_end
// in the ½-gain convention.
Solution solve(const Kernel& kernel, const MethodOptions& method, const IntegratorOptions& integrator,
               const std::vector<double>& c0_by_mass, double t_end);

// Mass that would be needed so that the leak past the cut-off falls below
// `tolerance` (a fraction of the total), estimated from the exponential decay
// of the tail between M/2 and M; rounded up to a power of two.
std::int64_t needed_cutoff(const MassGrid& grid, const std::vector<double>& c, double leaked, double tolerance);

}  // namespace coolgas::smoluchowski
