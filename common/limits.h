// Limits that more than one part of coolgas enforces, stated once.
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>

namespace coolgas {

// Particle ids and cell indices are 32-bit integers: at most this many
// particles, cells, and per-decade counts.
inline constexpr std::int64_t kMaxIndex32 = std::numeric_limits<std::int32_t>::max();

// The largest box side whose grid of floor(L)^3 unit cells has 32-bit
// indices (1290^3 < 2^31 <= 1291^3).
inline std::int64_t max_grid_side() { return std::int64_t(std::cbrt(double(kMaxIndex32))); }

}  // namespace coolgas
