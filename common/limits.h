// Limits that more than one part of coolgas enforces, stated once.
#pragma once
#include <cstdint>
#include <limits>

namespace coolgas {

// Particle ids and cell indices are 32-bit integers: at most this many
// particles, cells, and per-decade counts.
inline constexpr std::int64_t kMaxIndex32 = std::numeric_limits<std::int32_t>::max();

}  // namespace coolgas
