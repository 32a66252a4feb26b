#include "simulate/rsa_voxels.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "common/error.h"
#include "simulate/cell_grid.h"

namespace coolgas {

namespace {

// Plain trials are judged in windows of this many; when fewer than
// kSwitchAcceptance of a window succeed (the success rate of a plain trial is
// the free volume fraction), the voxel phase takes over.
constexpr std::int64_t kWindow = 4096;
constexpr double kSwitchAcceptance = 0.02;
// Voxel coordinates within their cell are 16-bit: at most 2^16 per side.
constexpr int kMaxLevel = 16;
// Total trials per sphere before giving up (only reachable if voxels at the
// finest level can never be removed, which needs a measure-zero arrangement).
constexpr double kMaxTrialsPerSphere = 2000;

// A voxel: a cube of side w / 2^level (w the cell width) inside one cell.
struct Voxel {
  std::int32_t cell;
  std::uint16_t x, y, z;  // corner within the cell, in voxel sides
};

class Placer {
 public:
  explicit Placer(Particles& p)
      : p_(p), grid_(p.L, 1.0, p.size()), L_(p.L), half_(p.L / 2), n_(grid_.cells_per_side()), w_(grid_.width()) {}

  void run(std::int64_t N, Random& rng);

 private:
  // Minimum image of a coordinate difference (|d| < L; L >= 3 > 2 diameters).
  double image(double d) const { return d > half_ ? d - L_ : (d < -half_ ? d + L_ : d); }
  int wrap(int k) const { return k < 0 ? k + n_ : (k >= n_ ? k - n_ : k); }

  // Calls f(position) for the spheres in the 27 cells around c until it returns true.
  template <class F>
  bool any_near(const CellCoord& c, F&& f) const {
    for (int oz = -1; oz <= 1; ++oz) {
      const int z = wrap(c.z + oz);
      for (int oy = -1; oy <= 1; ++oy) {
        const int row = (z * n_ + wrap(c.y + oy)) * n_;
        for (int ox = -1; ox <= 1; ++ox)
          for (int j = grid_.first(row + wrap(c.x + ox)); j >= 0; j = grid_.next(j))
            if (f(p_.r[std::size_t(j)])) return true;
      }
    }
    return false;
  }

  bool overlap(const Vec3& r, const Vec3& x) const {
    const double dx = image(r.x - x.x), dy = image(r.y - x.y), dz = image(r.z - x.z);
    return dx * dx + dy * dy + dz * dz < 1.0;
  }
  bool overlaps(const Vec3& x) const {
    return any_near(grid_.coord(grid_.cell_of(x.x, x.y, x.z)), [&](const Vec3& r) { return overlap(r, x); });
  }

  void place(std::int64_t i, const Vec3& x) {
    p_.r[std::size_t(i)] = x;
    grid_.insert(int(i), grid_.cell_of(x.x, x.y, x.z));
  }

  Vec3 uniform_in(const Vec3& lo, double side, Random& rng) const {
    Vec3 x;
    for (int d = 0; d < 3; ++d) x[d] = std::min(lo[d] + side * rng.uniform(), std::nextafter(L_, 0.0));
    return x;
  }

  // Whether the exclusion sphere (radius 1) around r holds the whole cube
  // [lo, lo + side]³: its farthest corner is inside. (Zhang & Torquato's
  // sufficient test; the union of several spheres may cover a voxel unseen,
  // which only leaves it listed a while longer.)
  bool covers(const Vec3& r, const Vec3& lo, double side) const {
    double far2 = 0;
    for (int d = 0; d < 3; ++d) {
      const double u = image(r[d] - lo[d]);
      const double f = std::max(std::abs(u), std::abs(u - side));
      far2 += f * f;
    }
    return far2 < 1.0;
  }

  double side(int level) const { return std::ldexp(w_, -level); }
  Vec3 corner(const Voxel& v, double s) const {
    const CellCoord c = grid_.coord(v.cell);
    return {c.x * w_ + v.x * s, c.y * w_ + v.y * s, c.z * w_ + v.z * s};
  }

  void gather_near(int cell);
  void refine(const Voxel& parent, int child_level);
  std::pair<int, std::size_t> draw_voxel(Random& rng) const;
  static void swap_remove(std::vector<Voxel>& list, std::size_t k) {
    list[k] = list.back();
    list.pop_back();
  }

  [[noreturn]] void saturated(std::int64_t placed, std::int64_t N) const;

  Particles& p_;
  CellGrid grid_;
  double L_, half_;
  int n_;
  double w_;
  std::vector<Vec3> near_;  // scratch: the spheres around one cell
  std::array<std::vector<Voxel>, kMaxLevel + 1> lists_;  // voxels of side w / 2^level
};

// The spheres that can reach any point of a cell (the 27 cells around it).
void Placer::gather_near(int cell) {
  near_.clear();
  any_near(grid_.coord(cell), [&](const Vec3& r) {
    near_.push_back(r);
    return false;
  });
}

// Replaces a voxel by its eight children, less those one exclusion sphere
// (of near_, gathered for its cell) covers.
void Placer::refine(const Voxel& parent, int child_level) {
  const double s = side(child_level);
  for (int b = 0; b < 8; ++b) {
    const Voxel child{parent.cell, std::uint16_t(2 * parent.x + (b & 1)), std::uint16_t(2 * parent.y + ((b >> 1) & 1)),
                      std::uint16_t(2 * parent.z + (b >> 2))};
    const Vec3 lo = corner(child, s);
    if (std::none_of(near_.begin(), near_.end(), [&](const Vec3& r) { return covers(r, lo, s); }))
      lists_[std::size_t(child_level)].push_back(child);
  }
}

void Placer::saturated(std::int64_t placed, std::int64_t N) const {
  char reached[32];
  std::snprintf(reached, sizeof reached, "%.4f", double(placed) * M_PI / (6.0 * L_ * L_ * L_));
  throw InputError(std::string("random sequential addition saturated at phi = ") + reached + " (placed " +
                   std::to_string(placed) + " of " + std::to_string(N) +
                   " spheres: no room is left for another); use system.init = \"fcc\" or a lower phi");
}

void Placer::run(std::int64_t N, Random& rng) {
  const double budget = kMaxTrialsPerSphere * double(N);
  double trials = 0;
  std::int64_t i = 0;

  // Plain phase: uniform over the box, rejected if overlapping.
  for (std::int64_t window_hits = 0, window = 0; i < N;) {
    const Vec3 x = uniform_in({0, 0, 0}, L_, rng);
    ++trials;
    if (!overlaps(x)) {
      place(i++, x);
      ++window_hits;
    }
    if (++window == kWindow) {
      if (double(window_hits) < kSwitchAcceptance * double(kWindow)) break;
      window = window_hits = 0;
    }
  }
  if (i == N) return;

  // Voxel phase (Zhang & Torquato 2013, with the refinement done voxel by
  // voxel): lists of voxels per level, a cell being the voxel of level 0.
  // Their union always holds all the free space: a voxel leaves its list
  // only when one exclusion sphere covers it, or when a trial in it failed,
  // in which case its uncovered children join the next level. A voxel drawn
  // with probability proportional to its volume, then a uniform point inside,
  // is a uniform point of the union: the process is still RSA.
  for (std::int64_t c = 0; c < grid_.cell_count(); ++c) lists_[0].push_back(Voxel{std::int32_t(c), 0, 0, 0});
  while (i < N) {
    if (trials > budget) saturated(i, N);
    const auto [level, k] = draw_voxel(rng);
    if (level < 0) saturated(i, N);
    std::vector<Voxel>& list = lists_[std::size_t(level)];
    const Voxel v = list[k];
    const double s = side(level);
    const Vec3 lo = corner(v, s);
    const Vec3 x = uniform_in(lo, s, rng);
    ++trials;
    // One pass over the 27 cells serves both the overlap test and, if the
    // point is rejected, the coverage test and the refinement.
    gather_near(v.cell);
    const bool free = grid_.cell_of(x.x, x.y, x.z) == v.cell
                          ? std::none_of(near_.begin(), near_.end(), [&](const Vec3& r) { return overlap(r, x); })
                          : !overlaps(x);  // x rounded onto the next cell
    if (free) {
      place(i++, x);
      if (covers(x, lo, s)) swap_remove(list, k);
      continue;
    }
    const bool covered = std::any_of(near_.begin(), near_.end(), [&](const Vec3& r) { return covers(r, lo, s); });
    if (!covered && level == kMaxLevel) continue;
    swap_remove(list, k);
    if (!covered) refine(v, level + 1);
  }
}

// A voxel with probability proportional to its volume (8^-level): a level
// by the total volume of its list, then a uniform index, from one uniform
// number. Returns level -1 when every list is empty (saturation).
std::pair<int, std::size_t> Placer::draw_voxel(Random& rng) const {
  double total = 0;
  for (int l = 0; l <= kMaxLevel; ++l) total += std::ldexp(double(lists_[std::size_t(l)].size()), -3 * l);
  if (total == 0) return {-1, 0};
  double u = rng.uniform() * total;
  int last = -1;
  for (int l = 0; l <= kMaxLevel; ++l) {
    const std::size_t count = lists_[std::size_t(l)].size();
    if (count == 0) continue;
    last = l;
    const double w = std::ldexp(double(count), -3 * l);
    if (u < w) return {l, std::min(count - 1, std::size_t(std::ldexp(u, 3 * l)))};
    u -= w;
  }
  return {last, lists_[std::size_t(last)].size() - 1};  // u rounded past the end
}

}  // namespace

void place_random_sequential(Particles& p, std::int64_t N, Random& rng) {
  Placer placer(p);
  placer.run(N, rng);
}

}  // namespace coolgas
