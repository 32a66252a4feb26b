// Particle storage: structure of arrays, one array per field, indexed by
// particle id. Positions are stored lazily: r[i] is particle i's position at
// its own time t[i]; its position at time T is r[i] + v[i] (T - t[i]).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

namespace coolgas {

struct Vec3 {
  double x = 0, y = 0, z = 0;
  double& operator[](int d) { return (&x)[d]; }
  double operator[](int d) const { return (&x)[d]; }
};
static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles (dumped as N x 3)");

inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 minus(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

using Image = std::array<std::int32_t, 3>;

struct Particles {
  double L = 0;                      // periodic box side
  std::vector<Vec3> r;               // position at time t[i], wrapped into the box
  std::vector<Vec3> v;               // velocity
  std::vector<double> t;             // time at which r[i] is valid
  std::vector<Image> image;          // periodic image counts (unwrapped = r + L * image)
  // Angular velocities of rough particles (collision_rules.h, RoughRule);
  // empty for smooth ones, whose spins never change and are not kept.
  std::vector<Vec3> omega;
  // The species of each particle of a mixture (collision_rules.h,
  // MixtureRule; an index into the scene's [[species]]); empty for equal
  // particles.
  std::vector<std::uint8_t> species;

  std::size_t size() const { return r.size(); }
  void resize(std::size_t n) {
    r.resize(n);
    v.resize(n);
    t.resize(n);
    image.resize(n);
  }
};

// Total momentum (unit masses), summed in id order with compensation
// (common/compensated_sum.h).
Vec3 total_momentum(const Particles& p);

}  // namespace coolgas
