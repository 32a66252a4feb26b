#include "simulate/start/rsa_free_point.h"

#include <cmath>
#include <cstddef>

namespace coolgas {

namespace {

// Candidates carry round-off, so a point counts as free unless it is nearer
// than 1 - kTolerance (squared) to a centre, and as inside the cube up to a
// relative kTolerance: erring that way only keeps a voxel listed.
constexpr double kTolerance = 1e-12;

Vec3 cross(const Vec3& a, const Vec3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// The points n · p = c equidistant from centres a and b.
struct Plane {
  Vec3 n;
  double c;
};
Plane bisector(const Vec3& a, const Vec3& b) { return {minus(b, a), 0.5 * (dot(b, b) - dot(a, a))}; }

class Search {
 public:
  Search(const Vec3& lo, double side, std::span<const Vec3> centres)
      : lo_(lo), hi_{lo.x + side, lo.y + side, lo.z + side}, slack_(kTolerance * side), centres_(centres) {}

  bool corners() const {
    for (int b = 0; b < 8; ++b)
      if (is_free({b & 1 ? hi_.x : lo_.x, b & 2 ? hi_.y : lo_.y, b & 4 ? hi_.z : lo_.z})) return true;
    return false;
  }

  // Points of the 12 edges on the plane.
  bool on_edges(const Plane& p) const {
    for (int a = 0; a < 3; ++a) {
      if (p.n[a] == 0) continue;
      const int b1 = (a + 1) % 3, b2 = (a + 2) % 3;
      for (int e = 0; e < 4; ++e) {
        Vec3 q;
        q[b1] = e & 1 ? hi_[b1] : lo_[b1];
        q[b2] = e & 2 ? hi_[b2] : lo_[b2];
        q[a] = (p.c - p.n[b1] * q[b1] - p.n[b2] * q[b2]) / p.n[a];
        if (inside(q) && is_free(q)) return true;
      }
    }
    return false;
  }

  // Points of the 6 faces on both planes.
  bool on_faces(const Plane& p, const Plane& r) const {
    for (int a = 0; a < 3; ++a) {
      const int b1 = (a + 1) % 3, b2 = (a + 2) % 3;
      const double det = p.n[b1] * r.n[b2] - p.n[b2] * r.n[b1];
      if (det == 0) continue;
      for (int f = 0; f < 2; ++f) {
        Vec3 q;
        q[a] = f ? hi_[a] : lo_[a];
        const double u = p.c - p.n[a] * q[a], v = r.c - r.n[a] * q[a];
        q[b1] = (u * r.n[b2] - v * p.n[b2]) / det;
        q[b2] = (p.n[b1] * v - r.n[b1] * u) / det;
        if (inside(q) && is_free(q)) return true;
      }
    }
    return false;
  }

  // The point inside on all three planes (Cramer's rule).
  bool within(const Plane& p, const Plane& r, const Plane& s) const {
    const Vec3 rs = cross(r.n, s.n), sp = cross(s.n, p.n), pr = cross(p.n, r.n);
    const double det = dot(p.n, rs);
    if (det == 0) return false;
    Vec3 q;
    for (int d = 0; d < 3; ++d) q[d] = (p.c * rs[d] + r.c * sp[d] + s.c * pr[d]) / det;
    return inside(q) && is_free(q);
  }

 private:
  bool inside(const Vec3& q) const {
    for (int d = 0; d < 3; ++d)
      if (q[d] < lo_[d] - slack_ || q[d] > hi_[d] + slack_) return false;
    return true;
  }
  bool is_free(const Vec3& q) const {
    for (const Vec3& c : centres_) {
      const Vec3 d = minus(q, c);
      if (dot(d, d) < 1.0 - kTolerance) return false;
    }
    return true;
  }

  Vec3 lo_, hi_;
  double slack_;
  std::span<const Vec3> centres_;
};

}  // namespace

bool holds_free_point(const Vec3& lo, double side, std::span<const Vec3> centres) {
  const Search search(lo, side, centres);
  if (search.corners()) return true;
  const std::size_t k = centres.size();
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = i + 1; j < k; ++j) {
      const Plane ij = bisector(centres[i], centres[j]);
      if (search.on_edges(ij)) return true;
      for (std::size_t m = j + 1; m < k; ++m) {
        const Plane im = bisector(centres[i], centres[m]);
        if (search.on_faces(ij, im)) return true;
        for (std::size_t q = m + 1; q < k; ++q)
          if (search.within(ij, im, bisector(centres[i], centres[q]))) return true;
      }
    }
  return false;
}

}  // namespace coolgas
