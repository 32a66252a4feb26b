#include "simulate/engine/particles.h"

#include "common/compensated_sum.h"

namespace coolgas {
double kinetic_energy_per_particle(const Particles& p) {
  CompensatedSum s;
  for (const Vec3& v : p.v) s.add(0.5 * dot(v, v));
  return s.value() / double(p.size());
}

Vec3 total_momentum(const Particles& p) {
  CompensatedSum s[3];
  for (const Vec3& v : p.v)
    for (int d = 0; d < 3; ++d) s[d].add(v[d]);
  return {s[0].value(), s[1].value(), s[2].value()};
}

}  // namespace coolgas
