#include "analyze/labelling/contact_labeller.h"

#include <numeric>

#include "common/close_pairs.h"

namespace coolgas {

std::int32_t ContactLabeller::find(std::int32_t x) {
  while (parent_[std::size_t(x)] != x) {
    parent_[std::size_t(x)] = parent_[std::size_t(parent_[std::size_t(x)])];  // path halving
    x = parent_[std::size_t(x)];
  }
  return x;
}

void ContactLabeller::unite(std::int32_t a, std::int32_t b) {
  a = find(a), b = find(b);
  if (a < b) parent_[std::size_t(b)] = a;
  else if (b < a) parent_[std::size_t(a)] = b;
}

void ContactLabeller::label(double L, std::span<const double> positions, double cutoff, Geometry g) {
  const std::size_t n = positions.size() / 3;
  parent_.resize(n);
  std::iota(parent_.begin(), parent_.end(), 0);
  std::vector<std::size_t> members(n);
  std::iota(members.begin(), members.end(), std::size_t(0));
  const double* p = positions.data();
  const double reach2 = cutoff * cutoff, half = 0.5 * L;
  for_each_close_pair(members, [p](std::size_t i) { return p + 3 * i; }, cutoff, L, g,
                      [&](std::size_t i, std::size_t j) {
                        double r2 = 0;
                        for (int k = 0; k < 3; ++k) {
                          double dx = std::abs(p[3 * j + k] - p[3 * i + k]);
                          dx = dx > half ? L - dx : dx;  // the minimum image (cutoff <= L/2)
                          r2 += dx * dx;
                        }
                        if (r2 < reach2) unite(std::int32_t(i), std::int32_t(j));
                      });
  // Roots are the smallest index of their trees, so one pass in increasing
  // order makes every parent a root and counts the masses into them.
  mass_.assign(n, 0);
  roots_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t r = parent_[std::size_t(parent_[i])];
    parent_[i] = r;
    if (r == std::int32_t(i)) roots_.push_back(r);
    ++mass_[std::size_t(r)];
  }
}

}  // namespace coolgas
