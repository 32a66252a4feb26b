// Which sub-cubes of a cube an exclusion sphere (radius 1) covers whole, and
// which it reaches into, as 64-bit masks over 4x4x4 sub-cubes: bit
// (z * 4 + y) * 4 + x for the sub-cube [x, x+1] s × [y, y+1] s × [z, z+1] s
// of the cube [0, 4s]^3, the sphere's centre r being relative to its corner.
//
// These masks are the inner loop of the voxel phase of random sequential
// addition (every voxel is tested against every centre near it), so they
// are computed four or eight sub-cubes at a time in single precision or
// 16-bit fixed point, from face coordinates rounded once from double (error
// below 3e-7 for coordinates below 4, so sums of squares near 1 are off by
// less than 2e-6). Every test leaves a margin far wider, at least 1e-5: a
// sub-cube counts as covered only if its farthest corner is nearer than
// 1 - 1e-5, which is what matters for exactness (covered space is never
// sampled again, so it must really be covered); "reaches" is only a filter
// that spares work, and counting a sphere as reaching where it does not is
// harmless. Everything is inline: the calls cost as much as the work.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "simulate/engine/particles.h"

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace coolgas {

namespace sub_cubes {

// Covered below 1 - kSlack, reached below 1 + kSlack (squared distances).
constexpr float kSlack = 1e-5f;

// Squared distances from the coordinate u to the farther face of the slabs
// [k s, (k + 1) s], k = first .. first + 3 (far), and to the slabs (near, 0 inside).
inline void slab_distances(double u, double s, int first, float far[4], float near[4]) {
#ifdef __SSE2__
  const __m128d uu = _mm_set1_pd(u), ss = _mm_set1_pd(s);
  const auto face = [&](int k0) {  // faces k0, k0 + 1 in double, rounded once
    return _mm_cvtpd_ps(_mm_sub_pd(uu, _mm_mul_pd(ss, _mm_setr_pd(k0, k0 + 1))));
  };
  const __m128 lo = _mm_movelh_ps(face(first), face(first + 2));
  const __m128 hi = _mm_movelh_ps(face(first + 1), face(first + 3));
  const __m128 sign = _mm_set1_ps(-0.0f);
  const __m128 f = _mm_max_ps(_mm_andnot_ps(sign, lo), _mm_andnot_ps(sign, hi));
  _mm_storeu_ps(far, _mm_mul_ps(f, f));
  if (near != nullptr) {
    const __m128 q = _mm_max_ps(_mm_max_ps(_mm_xor_ps(sign, lo), hi), _mm_setzero_ps());
    _mm_storeu_ps(near, _mm_mul_ps(q, q));
  }
#else
  for (int k = 0; k < 4; ++k) {
    const float lo = float(u - (first + k) * s), hi = float(u - (first + k + 1) * s);
    const float f = std::max(std::abs(lo), std::abs(hi));
    far[k] = f * f;
    if (near != nullptr) {
      const float q = std::max(std::max(-lo, hi), 0.0f);
      near[k] = q * q;
    }
  }
#endif
}

// The bits of the 4x4x4 sub-cubes with dx[x] + dy[y] + dz[z] < limit.
inline std::uint64_t below(const float dx[4], const float dy[4], const float dz[4], float limit) {
#ifdef __SSE2__
  const __m128 vx = _mm_loadu_ps(dx);
  const __m128 vy = _mm_loadu_ps(dy);
  std::uint64_t mask = 0;
  for (int z = 0; z < 4; ++z) {  // no early exit: the branch would be unpredictable
    const __m128 t = _mm_sub_ps(_mm_set1_ps(limit - dz[z]), vy);  // per y: what is left for x
    const unsigned r0 = unsigned(_mm_movemask_ps(_mm_cmplt_ps(vx, _mm_shuffle_ps(t, t, 0x00))));
    const unsigned r1 = unsigned(_mm_movemask_ps(_mm_cmplt_ps(vx, _mm_shuffle_ps(t, t, 0x55))));
    const unsigned r2 = unsigned(_mm_movemask_ps(_mm_cmplt_ps(vx, _mm_shuffle_ps(t, t, 0xaa))));
    const unsigned r3 = unsigned(_mm_movemask_ps(_mm_cmplt_ps(vx, _mm_shuffle_ps(t, t, 0xff))));
    mask |= std::uint64_t(r0 | r1 << 4 | r2 << 8 | r3 << 12) << (16 * z);
  }
  return mask;
#else
  std::uint64_t mask = 0;
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 4; ++y) {
      const float t = limit - dz[z] - dy[y];
      const unsigned row = unsigned(dx[0] < t) | unsigned(dx[1] < t) << 1 | unsigned(dx[2] < t) << 2 |
                           unsigned(dx[3] < t) << 3;
      mask |= std::uint64_t(row) << ((z * 4 + y) * 4);
    }
  return mask;
#endif
}

}  // namespace sub_cubes

// The single-sphere tests on one cube [lo, lo + side]^3, with the same margin.
inline bool covers_cube(const Vec3& r, const Vec3& lo, double side) {
  double far2 = 0;
  for (int d = 0; d < 3; ++d) {
    const double u = r[d] - lo[d];
    const double f = std::max(std::abs(u), std::abs(u - side));
    far2 += f * f;
  }
  return far2 < 1.0 - double(sub_cubes::kSlack);
}

inline bool reaches_cube(const Vec3& r, const Vec3& lo, double side) {
  double near2 = 0;
  for (int d = 0; d < 3; ++d) {
    const double u = r[d] - lo[d];
    const double q = std::max(std::max(-u, u - side), 0.0);
    near2 += q * q;
  }
  return near2 < 1.0 + double(sub_cubes::kSlack);
}

// The 4x4x4 sub-cubes of side s that the sphere at r covers.
inline std::uint64_t covered_sub_cubes(const Vec3& r, double s) {
  float far[3][4];
  for (int d = 0; d < 3; ++d) sub_cubes::slab_distances(r[d], s, 0, far[d], nullptr);
  return sub_cubes::below(far[0], far[1], far[2], 1.0f - sub_cubes::kSlack);
}

namespace sub_cubes {

// The views below hold squared distances in 16-bit fixed point, kUnit per
// unit, rounded up (so a sum below kCoveredBelow means a true sum below
// 4095/4096 + 6e-6 < 1 - 2e-4: covered, with room to spare); 16 bits let
// one instruction compare eight sub-cubes instead of four.
constexpr float kUnit = 4096;
constexpr int kCoveredBelow = 4095;

// Fixed point, rounded up (and saturated): one more than the truncation.
inline void to_fixed(const float v[8], std::int16_t q[8]) {
#ifdef __SSE2__
  const __m128 unit = _mm_set1_ps(kUnit);
  const __m128i one = _mm_set1_epi32(1);
  const __m128i a = _mm_add_epi32(_mm_cvttps_epi32(_mm_mul_ps(_mm_loadu_ps(v), unit)), one);
  const __m128i b = _mm_add_epi32(_mm_cvttps_epi32(_mm_mul_ps(_mm_loadu_ps(v + 4), unit)), one);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(q), _mm_packs_epi32(a, b));
#else
  for (int k = 0; k < 8; ++k) q[k] = std::int16_t(std::min(32767.0f, std::floor(v[k] * kUnit) + 1));
#endif
}

// The bits of the 4x4x4 sub-cubes with qx[x] + qy[y] + qz[z] < kCoveredBelow.
inline std::uint64_t below_fixed(const std::int16_t qx[4], const std::int16_t qy[4], const std::int16_t qz[4]) {
  std::uint64_t mask = 0;
#ifdef __SSE2__
  // Lanes: x0..x3 for one y, then x0..x3 for the next; the comparisons of
  // two such pairs of rows pack into the 16 bits of one z, in bit order.
  const __m128i x4 = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(qx));
  const __m128i x8 = _mm_unpacklo_epi64(x4, x4);
  const __m128i y = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(qy));
  const __m128i yy = _mm_unpacklo_epi16(y, y);
  const __m128i y01 = _mm_unpacklo_epi32(yy, yy), y23 = _mm_unpackhi_epi32(yy, yy);
  for (int z = 0; z < 4; ++z) {
    const __m128i left = _mm_set1_epi16(std::int16_t(std::max(kCoveredBelow - qz[z], -32768)));  // what is left for x + y
    const __m128i lo = _mm_cmplt_epi16(x8, _mm_subs_epi16(left, y01));
    const __m128i hi = _mm_cmplt_epi16(x8, _mm_subs_epi16(left, y23));
    mask |= std::uint64_t(unsigned(_mm_movemask_epi8(_mm_packs_epi16(lo, hi)))) << (16 * z);
  }
#else
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x)
        if (int(qx[x]) + qy[y] + qz[z] < kCoveredBelow) mask |= std::uint64_t(1) << ((z * 4 + y) * 4 + x);
#endif
  return mask;
}

}  // namespace sub_cubes

// A cell is cut twice 4x4x4: 64 coarse cubes of 64 voxels each (side s =
// w/16). Along one axis, a centre's coordinate u relative to a cell's corner
// against the cell's 4 coarse slabs and, if asked, its 16 voxel slabs (the
// squared distance to each slab's farther face, in fixed point): computed
// once per centre and cell column, shared by the cells of the column.
struct AxisView {
  AxisView() = default;
  AxisView(double u, double voxel_side, bool voxels);
  std::int16_t coarse_far[8];  // 4 used
  std::int16_t voxel_far[16];
  std::int16_t nearest_far[4];  // per coarse slab, the least of its voxel slabs' far distances
  // The least far distance of any coarse slab, and of any voxel slab: a cell
  // where the three axes' sum is not below the limit has nothing covered.
  int least_coarse_far, least_voxel_far;
};

inline AxisView::AxisView(double u, double voxel_side, bool voxels) {
  // The 17 voxel faces u - k s (k = 0..16), each rounded once to single
  // precision; a slab's far distance is the larger of its two faces'.
  alignas(16) float face[20];
  float far[16];
#ifdef __SSE2__
  const __m128d uu = _mm_set1_pd(u), ss = _mm_set1_pd(voxel_side);
  for (int k = 0; k < 20; k += 4) {
    const __m128d a = _mm_sub_pd(uu, _mm_mul_pd(ss, _mm_setr_pd(k, k + 1)));
    const __m128d b = _mm_sub_pd(uu, _mm_mul_pd(ss, _mm_setr_pd(k + 2, k + 3)));
    _mm_store_ps(face + k, _mm_movelh_ps(_mm_cvtpd_ps(a), _mm_cvtpd_ps(b)));
  }
  const __m128 sign = _mm_set1_ps(-0.0f);
  const auto far2 = [&](__m128 a, __m128 b) {
    const __m128 f = _mm_max_ps(_mm_andnot_ps(sign, a), _mm_andnot_ps(sign, b));
    return _mm_mul_ps(f, f);
  };
  _mm_storeu_ps(far, far2(_mm_setr_ps(face[0], face[4], face[8], face[12]), _mm_setr_ps(face[4], face[8], face[12], face[16])));
  _mm_storeu_ps(far + 4, _mm_setzero_ps());
  sub_cubes::to_fixed(far, coarse_far);
  if (voxels)
    for (int q = 0; q < 4; ++q) _mm_storeu_ps(far + 4 * q, far2(_mm_load_ps(face + 4 * q), _mm_loadu_ps(face + 4 * q + 1)));
#else
  for (int k = 0; k <= 16; ++k) face[k] = float(u - k * voxel_side);
  const auto far2 = [](float a, float b) {
    const float f = std::max(std::abs(a), std::abs(b));
    return f * f;
  };
  for (int q = 0; q < 8; ++q) far[q] = q < 4 ? far2(face[4 * q], face[4 * q + 4]) : 0.0f;
  sub_cubes::to_fixed(far, coarse_far);
  if (voxels)
    for (int k = 0; k < 16; ++k) far[k] = far2(face[k], face[k + 1]);
#endif
  least_coarse_far = std::min(std::min(coarse_far[0], coarse_far[1]), std::min(coarse_far[2], coarse_far[3]));
  if (!voxels) return;
  sub_cubes::to_fixed(far, voxel_far);
  sub_cubes::to_fixed(far + 8, voxel_far + 8);
  for (int q = 0; q < 4; ++q) {
    const std::int16_t* f = voxel_far + 4 * q;
    nearest_far[q] = std::min(std::min(f[0], f[1]), std::min(f[2], f[3]));
  }
  least_voxel_far = std::min(std::min(nearest_far[0], nearest_far[1]), std::min(nearest_far[2], nearest_far[3]));
}

// One sphere seen from one cell, through its three axis views.
class SphereOverCell {
 public:
  SphereOverCell(const AxisView& x, const AxisView& y, const AxisView& z) : x_(x), y_(y), z_(z) {}
  // Whether it may cover a coarse cube, or a voxel, of the cell at all.
  bool may_cover_coarse() const {
    return x_.least_coarse_far + y_.least_coarse_far + z_.least_coarse_far < sub_cubes::kCoveredBelow;
  }
  bool may_cover_voxel() const {
    return x_.least_voxel_far + y_.least_voxel_far + z_.least_voxel_far < sub_cubes::kCoveredBelow;
  }
  // Coarse cubes it covers whole.
  std::uint64_t covered_coarse() const { return sub_cubes::below_fixed(x_.coarse_far, y_.coarse_far, z_.coarse_far); }
  // Coarse cubes in which it covers at least one voxel (the views with
  // voxels): the far distance is a sum over axes, so its least value over a
  // coarse cube's voxels is the sum of the least values along each axis.
  std::uint64_t covering_coarse() const {
    return sub_cubes::below_fixed(x_.nearest_far, y_.nearest_far, z_.nearest_far);
  }
  // The voxels of one coarse cube it covers whole (the views with voxels).
  std::uint64_t covered_voxels(int coarse) const {
    const int x = coarse & 3, y = (coarse >> 2) & 3, z = coarse >> 4;
    return sub_cubes::below_fixed(x_.voxel_far + 4 * x, y_.voxel_far + 4 * y, z_.voxel_far + 4 * z);
  }

 private:
  const AxisView &x_, &y_, &z_;
};

// The corner of sub-cube `bit` of a cube at lo cut 4x4x4 with sides s.
inline Vec3 sub_cube_corner(const Vec3& lo, int bit, double s) {
  return {lo.x + (bit & 3) * s, lo.y + ((bit >> 2) & 3) * s, lo.z + (bit >> 4) * s};
}

}  // namespace coolgas
