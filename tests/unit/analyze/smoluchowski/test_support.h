// Small helpers shared by the Smoluchowski tests.
#pragma once
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "analyze/smoluchowski/initial.h"
#include "analyze/smoluchowski/solve.h"

namespace coolgas::smoluchowski::testing {

inline Solution run(const std::string& kernel, Method method, std::int64_t M, double t, double rtol = 1e-10,
                    double atol = 1e-18, Stepper stepper = Stepper::Rkck, double ratio = 1.05) {
  MethodOptions mo;
  mo.method = method;
  mo.M = M;
  mo.grid_ratio = ratio;
  return solve(parse_kernel(kernel), mo, {rtol, atol, stepper}, initial_masses("mono", mo.M), t);
}

inline double peak(const std::vector<double>& c) { return *std::max_element(c.begin(), c.end()); }

// max_k |a_k − b_k| relative to the largest b_k.
inline double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0;
  for (std::size_t k = 0; k < a.size(); ++k) d = std::max(d, std::abs(a[k] - b[k]));
  return d / peak(b);
}

}  // namespace coolgas::smoluchowski::testing
