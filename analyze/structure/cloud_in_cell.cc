#include "analyze/structure/cloud_in_cell.h"

#include <cstdint>

namespace coolgas {

namespace {

// Lower grid point and the weight of the upper one along one axis.
struct Split {
  int lo, hi;
  double f;
};

Split split(double x, double scale, int n) {
  double s = x * scale;
  s -= n * std::floor(s / n);  // periodic wrap, also for x a round-off outside [0, L)
  int lo = static_cast<int>(s);
  double f = s - lo;
  if (lo >= n) lo -= n;        // s rounded up to n
  return {lo, lo + 1 == n ? 0 : lo + 1, f};
}

}  // namespace

void CloudInCell::assign(FourierGrid& grid, double L, std::span<const double> positions,
                         std::span<const double> weights) {
  // depth 1 in 2D: every z is 0, one plane; height 1 too in 1D: every y is 0, one row
  const int n = grid.n(), depth = grid.depth(), height = grid.height();
  const double scale = n / L;
  const std::size_t count = positions.size() / 3;
  // Counting sort by the lower z plane.
  plane_.resize(count);
  start_.assign(std::size_t(depth) + 1, 0);
  for (std::size_t p = 0; p < count; ++p) {
    plane_[p] = std::uint16_t(split(positions[3 * p + 2], scale, depth).lo);
    ++start_[plane_[p] + 1];
  }
  for (int k = 0; k < depth; ++k) start_[k + 1] += start_[k];
  sorted_.resize(count);
  for (std::size_t p = 0; p < count; ++p)
    sorted_[start_[plane_[p]]++] = {positions[3 * p], positions[3 * p + 1], positions[3 * p + 2],
                                    weights.empty() ? 1.0 : weights[p]};
  double* g = grid.real();
  for (const Point& q : sorted_) {
    const Split x = split(q.x, scale, n), y = split(q.y, scale, height), z = split(q.z, scale, depth);
    const double wx[2] = {1 - x.f, x.f}, wy[2] = {1 - y.f, y.f}, wz[2] = {q.w * (1 - z.f), q.w * z.f};
    const int iy[2] = {y.lo, y.hi}, iz[2] = {z.lo, z.hi};
    for (int c = 0; c < 2; ++c)
      for (int b = 0; b < 2; ++b) {
        double* row = g + grid.real_index(0, iy[b], iz[c]);
        const double w = wy[b] * wz[c];
        row[x.lo] += wx[0] * w;
        row[x.hi] += wx[1] * w;
      }
  }
}

}  // namespace coolgas
