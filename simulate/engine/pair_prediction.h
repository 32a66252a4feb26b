// When do two moving spheres touch (unit diameters, or a mixture's pair)? The one formula both
// engines use, so that the fast engine can be checked against the reference.
#pragma once
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "simulate/engine/particles.h"

namespace coolgas {

inline constexpr double kNever = std::numeric_limits<double>::infinity();

// dr = r_j - r_i and dv = v_j - v_i at the same instant; returns the time
// from that instant until contact (|dr| = sigma), or kNever if they do not
// approach or miss. A pair found overlapping by round-off while approaching
// collides at once (returns 0), so nothing ever tunnels through another.
inline double time_to_contact(const Vec3& dr, const Vec3& dv, double sigma2 = 1.0) {
  const double b = dot(dr, dv);
  if (b >= 0) return kNever;  // moving apart or sideways
  const double gap2 = dot(dr, dr) - sigma2;
  if (gap2 <= 0) return 0.0;  // overlapping by round-off and approaching
  const double v2 = dot(dv, dv);
  const double disc = b * b - v2 * gap2;
  if (disc <= 0) return kNever;  // they miss
  // gap2 / (-b + sqrt(disc)) equals (-b - sqrt(disc)) / v2 without its cancellation.
  return gap2 / (-b + std::sqrt(disc));
}

// As time_to_contact, but kNever for any contact not earlier than `limit`,
// decided before the square root where possible: contact cannot come before
// gap2 / (2|b|), since sqrt(disc) <= |b|. The margin keeps the shortcut from
// ever rejecting a time that would round below `limit`, so the result equals
// time_to_contact whenever that is < limit.
inline double time_to_contact_before(const Vec3& dr, const Vec3& dv, double limit, double sigma2 = 1.0) {
  const double b = dot(dr, dv);
  if (b >= 0) return kNever;
  const double gap2 = dot(dr, dr) - sigma2;
  if (gap2 <= 0) return 0.0;
  if (gap2 > -2.0 * b * limit * (1.0 + 1e-12)) return kNever;
  const double v2 = dot(dv, dv);
  const double disc = b * b - v2 * gap2;
  if (disc <= 0) return kNever;
  return gap2 / (-b + std::sqrt(disc));
}

// time_to_contact (the same value, up to the sign of a zero result) without
// data-dependent branches, for the engine's partner search: whether a
// candidate approaches, misses or overlaps is a coin toss the branch
// predictor loses, and mispredictions cost more than computing the square
// root every time. The final choice is made on the bits, so the compiler
// cannot turn it back into a branch. A particle paired with itself (dr = 0)
// gets kNever. sigma2 is the squared contact distance: 1 for unit spheres
// (a constant the compiler folds, so their search is the code it was), the
// pair's ((sigma_i + sigma_j) / 2)^2 in a mixture.
inline double time_to_contact_unbranched(const Vec3& dr, const Vec3& dv, double sigma2 = 1.0) {
  const double b = dot(dr, dv);
  const double gap2 = dot(dr, dr) - sigma2;
  const double disc = b * b - dot(dv, dv) * gap2;
  // gap2 <= 0 (overlap by round-off) gives 0: contact at once.
  // |disc| rather than max(disc, 0), which the compiler makes a branch around
  // the root; where disc <= 0 matters the result is 0 or not a hit anyway.
  const double t = std::max(gap2, 0.0) / (-b + std::sqrt(std::abs(disc)));
  const bool hit = (b < 0) & ((gap2 <= 0) | (disc > 0));
  const std::uint64_t keep = -std::uint64_t(hit);
  return std::bit_cast<double>((std::bit_cast<std::uint64_t>(t) & keep) |
                               (std::bit_cast<std::uint64_t>(kNever) & ~keep));
}

// Applies the paper's Eq. (1) to velocities vi, vj with the unit normal n
// pointing from i to j: the normal relative velocity is reversed and scaled
// by r, the tangential one unchanged, momentum conserved. g = n·(vi − vj) > 0
// is the normal relative speed before the collision.
inline void apply_restitution(Vec3& vi, Vec3& vj, const Vec3& n, double g, double r) {
  const double k = 0.5 * (1.0 + r) * g;
  for (int d = 0; d < 3; ++d) {
    vi[d] -= k * n[d];
    vj[d] += k * n[d];
  }
}

// apply_restitution for unequal masses mi, mj (a mixture): the impulse
// (1 + r) g mi mj / (mi + mj) along n, so the momentum is kept and the
// normal relative velocity reversed and scaled by r, the tangential ones
// unchanged.
inline void apply_restitution_with_masses(Vec3& vi, Vec3& vj, const Vec3& n, double g, double r, double mi,
                                          double mj) {
  const double k = (1.0 + r) * g / (mi + mj);
  const double ki = k * mj, kj = k * mi;
  for (int d = 0; d < 3; ++d) {
    vi[d] -= ki * n[d];
    vj[d] += kj * n[d];
  }
}

// The tangential part of a rough collision (Walton 1993; Huthmann &
// Zippelius 1997) between unit-diameter spheres (radius a = 1/2, mass 1)
// with spins wi, wj, the unit normal n pointing from i to j: the contact
// points' relative velocity is v_i - v_j + a (w_i + w_j) x n, and its
// tangential part g_t becomes -beta g_t. The impulse -eta_t g_t on i (+ on
// j), eta_t = q (1 + beta) / (2 (1 + q)), turns both spins by
// a n x P / I = -(1 + beta) / (1 + q) n x g_t (I = q a^2). The normal part
// is apply_restitution's, which commutes with this one (g_t has no normal
// part, and the impulse here none either): call this one first, on the
// velocities before either. In 2D every z term of the velocities and the
// x, y terms of the spins are exact zeros and stay so.
inline void apply_tangential_restitution(Vec3& vi, Vec3& vj, Vec3& wi, Vec3& wj, const Vec3& n, double eta_t,
                                         double spin_turn) {
  const Vec3 w{0.5 * (wi.x + wj.x), 0.5 * (wi.y + wj.y), 0.5 * (wi.z + wj.z)};  // a (w_i + w_j)
  const Vec3 g{vi.x - vj.x + (w.y * n.z - w.z * n.y), vi.y - vj.y + (w.z * n.x - w.x * n.z),
               vi.z - vj.z + (w.x * n.y - w.y * n.x)};
  const double gn = dot(g, n);
  const Vec3 gt{g.x - gn * n.x, g.y - gn * n.y, g.z - gn * n.z};
  const Vec3 turn{spin_turn * (n.y * gt.z - n.z * gt.y), spin_turn * (n.z * gt.x - n.x * gt.z),
                  spin_turn * (n.x * gt.y - n.y * gt.x)};
  for (int d = 0; d < 3; ++d) {
    vi[d] -= eta_t * gt[d];
    vj[d] += eta_t * gt[d];
    wi[d] -= turn[d];
    wj[d] -= turn[d];
  }
}

}  // namespace coolgas
