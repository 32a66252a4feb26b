#include "simulate/engine/particles.h"

#include "common/compensated_sum.h"

namespace coolgas {
Vec3 total_momentum(const Particles& p) {
  CompensatedSum s[3];
  for (const Vec3& v : p.v)
    for (int d = 0; d < 3; ++d) s[d].add(v[d]);
  return {s[0].value(), s[1].value(), s[2].value()};
}

}  // namespace coolgas
