// A 2D file's per-particle rows (2 numbers each) as the 3-vectors every
// reader and the engine use, with z = 0: disks are spheres confined to the
// plane z = 0 (simulate/engine/engine.h). A 1D file's rows (1 number each)
// widen the same way, y = z = 0: rods on the x axis.
#pragma once
#include <cstddef>
#include <vector>

namespace coolgas {

// Spreads n rows of d numbers (the first n d entries of v) to rows of 3, the
// missing components 0, in place (from the last row back, so no row is
// overwritten before it is moved).
template <class T>
void widen_to_three(std::vector<T>& v, std::size_t n, std::size_t d) {
  if (d == 3) return;
  v.resize(3 * n);
  for (std::size_t i = n; i-- > 0;) {
    const std::size_t from = i * d, to = 3 * i;
    for (std::size_t k = 3; k-- > 0;) v[to + k] = k < d ? v[from + k] : T{};
  }
}

}  // namespace coolgas
