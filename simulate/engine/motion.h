// A particle's motion record (what the partner search reads of a candidate,
// in one cache line) and the two operations every engine applies to it:
// moving a position to a later time and wrapping it into the box.
#pragma once
#include <cstdint>

#include "simulate/engine/particles.h"

namespace coolgas {

// Everything the partner search reads of a particle, in one cache line.
struct alignas(64) Motion {
  Vec3 r;               // position at time t (wrapped into the box up to round-off)
  Vec3 v;               // velocity
  double t;             // time at which r is valid
  std::uint32_t count;  // collisions since the last rebuild (lazy invalidation)
  std::int32_t next;    // next particle in the same cell (the cell grid's list link, or the large-aggregate index's)
};
static_assert(sizeof(Motion) == 64, "one cache line per particle");

// The position of m at time `now` (each component r + v (now - t), in that
// order of operations, so a copy and the record itself move identically).
inline Vec3 position_at(const Motion& m, double now) {
  const double dt = now - m.t;
  return {m.r.x + m.v.x * dt, m.r.y + m.v.y * dt, m.r.z + m.v.z * dt};
}

// Wraps r into [0, L) along each axis, counting the box sides crossed in image.
inline void wrap_into_box(Vec3& r, Image& image, double L) {
  for (int d = 0; d < 3; ++d) {
    double& x = r[d];
    while (x >= L) x -= L, ++image[d];
    while (x < 0) x += L, --image[d];
    if (x >= L) x = 0;  // x was -tiny and x + L rounded up to L
  }
}

}  // namespace coolgas
