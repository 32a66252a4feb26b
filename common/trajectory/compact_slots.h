// Dropping the empty slots of a per-particle array (ballistic aggregation
// keeps a slot per initial particle; a merged one is empty).
#pragma once
#include <cstddef>
#include <vector>

namespace coolgas {

// Moves the entries of present slots (present[i]) to the front, `k` numbers
// each, and drops the rest; an empty v (a field not read) stays empty.
template <class T>
void compact_slots(std::vector<T>& v, const std::vector<bool>& present, std::size_t k) {
  if (v.empty()) return;
  std::size_t out = 0;
  for (std::size_t i = 0; i < present.size(); ++i) {
    if (!present[i]) continue;
    for (std::size_t c = 0; c < k; ++c) v[out * k + c] = v[i * k + c];
    ++out;
  }
  v.resize(out * k);
}

}  // namespace coolgas
