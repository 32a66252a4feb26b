#include "analyze/smoluchowski/solve.h"

#include <bit>
#include <cmath>

#include "analyze/smoluchowski/initial.h"

namespace coolgas::smoluchowski {

Solution solve(const Kernel& kernel, const MethodOptions& method, const IntegratorOptions& integrator,
               const std::vector<double>& c0_by_mass, double t_end) {
  auto rhs = make_rhs(kernel, method);
  Integrator it(*rhs, on_grid(rhs->grid(), c0_by_mass), integrator);
  it.advance_to(t_end);
  return {rhs->grid(), it.state(), it.time(), it.steps(), it.evaluations()};
}

std::int64_t needed_cutoff(const MassGrid& grid, const std::vector<double>& c, double leaked, double tolerance) {
  const std::int64_t M = grid.cutoff();
  // Concentration per integer mass near M/2 and at M.
  std::size_t mid = 0;
  while (mid + 1 < grid.size() && grid.mass[mid] < 0.5 * double(M)) ++mid;
  const std::size_t last = grid.size() - 1;
  const double c1 = c[mid] / grid.width(mid), c2 = c[last] / grid.width(last);
  double want = 2.0 * double(M);  // without a decaying tail to go by
  if (c1 > c2 && c2 > 0) {
    const double decay_length = (grid.mass[last] - grid.mass[mid]) / std::log(c1 / c2);
    want = std::max(want, double(M) + decay_length * std::log(std::max(leaked / tolerance, 1.0)));
  }
  return static_cast<std::int64_t>(std::bit_ceil(static_cast<std::uint64_t>(std::ceil(want))));
}

}  // namespace coolgas::smoluchowski
