#include "analyze/labelling/contact_labeller.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>

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

void ContactLabeller::label(double L, std::span<const double> positions, double cutoff, Geometry g,
                            std::span<const double> diameter) {
  const std::size_t n = positions.size() / 3;
  if (!diameter.empty() && diameter.size() != n) throw std::logic_error("ContactLabeller: a diameter per particle");
  // The union-find runs over the points in cell order (PairsWithin's), where
  // bonded points lie near each other in memory too; in the caller's order
  // (random in space) each find missed the cache.
  const double widest = diameter.empty() ? 1.0 : *std::max_element(diameter.begin(), diameter.end());
  const PairsWithin pairs(positions, cutoff * widest, L, g);
  parent_.resize(n);
  std::iota(parent_.begin(), parent_.end(), 0);
  if (diameter.empty()) {
    pairs.for_each([&](std::size_t a, std::size_t b, double) { unite(std::int32_t(a), std::int32_t(b)); });
  } else {  // a mixture: the pairs within the widest pair's reach, bonded within their own
    const double half = cutoff / 2;
    pairs.for_each([&](std::size_t a, std::size_t b, double r2) {
      const double reach = half * (diameter[pairs.index(a)] + diameter[pairs.index(b)]);
      if (r2 < reach * reach) unite(std::int32_t(a), std::int32_t(b));
    });
  }
  // Each tree's smallest caller index (at its root), then every particle's
  // in the caller's numbering: the root the labeller's contract names.
  std::vector<std::int32_t> smallest(n, std::numeric_limits<std::int32_t>::max()), root(n);
  for (std::size_t a = 0; a < n; ++a) {
    std::int32_t& s = smallest[std::size_t(find(std::int32_t(a)))];
    s = std::min(s, std::int32_t(pairs.index(a)));
  }
  for (std::size_t a = 0; a < n; ++a) root[pairs.index(a)] = smallest[std::size_t(find(std::int32_t(a)))];
  parent_.swap(root);
  // Every parent is now a root: count the masses into them, in increasing order.
  mass_.assign(n, 0);
  roots_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t r = parent_[i];
    if (r == std::int32_t(i)) roots_.push_back(r);
    ++mass_[std::size_t(r)];
  }
}

}  // namespace coolgas
