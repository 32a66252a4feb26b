#include "simulate/start/rod_placement.h"

#include <algorithm>
#include <cmath>

namespace coolgas {

void place_rods(Particles& p, std::int64_t N, Random& rng, InterruptFlag interrupt, const PlacementReport& report) {
  const double L = p.L, free_length = L - double(N);
  const auto n = std::size_t(N);
  for (std::size_t i = 0; i < n; ++i) {
    if ((i & 0xffff) == 0) {
      throw_if_interrupted(interrupt);
      if (report) report(std::int64_t(i));
    }
    p.r[i] = {rng.uniform() * free_length, 0.0, 0.0};
  }
  std::sort(p.r.begin(), p.r.begin() + std::ptrdiff_t(n), [](const Vec3& a, const Vec3& b) { return a.x < b.x; });
  const double offset = rng.uniform() * L;
  double before = -INFINITY;
  for (std::size_t i = 0; i < n; ++i) {
    // offset + u_i + i, kept at least one rod length past the rod before
    // (the sum's rounding could leave it an ulp short).
    double x = offset + p.r[i].x + double(i);
    while (x - before < 1.0) x = std::nextafter(x, INFINITY);
    before = x;
    p.r[i].x = x < L ? x : x - L;  // exact: L <= x < 2 L
  }
}

}  // namespace coolgas
