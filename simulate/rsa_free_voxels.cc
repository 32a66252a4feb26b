#include "simulate/rsa_free_voxels.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "simulate/rsa_free_point.h"
#include "simulate/rsa_sub_cubes.h"

namespace coolgas {

namespace {

// Set bits of a mask. Without the POPCNT instruction (the portable build)
// std::popcount is a library call; this is the same count in a few
// arithmetic steps (Hacker's Delight, 5-2).
int bit_count(std::uint64_t m) {
#ifdef __POPCNT__
  return std::popcount(m);
#else
  m -= (m >> 1) & 0x5555555555555555ULL;
  m = (m & 0x3333333333333333ULL) + ((m >> 2) & 0x3333333333333333ULL);
  m = (m + (m >> 4)) & 0x0f0f0f0f0f0f0f0fULL;
  return int((m * 0x0101010101010101ULL) >> 56);
#endif
}

int nth_set_bit(std::uint64_t m, std::uint64_t k) {
  for (; k > 0; --k) m &= m - 1;
  return std::countr_zero(m);
}

int rank_of(std::uint64_t listed, int bit) { return bit_count(listed & ((std::uint64_t(1) << bit) - 1)); }

Vec3 minus(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

// A uniform integer in [0, range) (range > 0): the top bits of one draw,
// rejected until below range (exact, and fewer than two draws on average).
std::uint64_t uniform_below(Random& rng, std::uint64_t range) {
  const int drop = std::countl_zero(range);
  for (;;) {
    const std::uint64_t u = rng.next() >> drop;
    if (u < range) return u;
  }
}

}  // namespace

FreeVoxels::FreeVoxels(std::size_t cells, double cell_width) : w_(cell_width), cells_(cells), tree_(cells) {
  // A whole cell weighs 8^finest; bricks refine two levels at a time from level 4.
  finest_ = std::min(16, ((62 - int(std::bit_width(cells))) / 3) & ~1);
}

double FreeVoxels::side(int level) const { return std::ldexp(w_, -level); }

std::uint64_t FreeVoxels::weight_of(std::uint64_t mask, int level) const {
  return std::uint64_t(bit_count(mask)) << shift(level);
}

Vec3 FreeVoxels::brick_corner(std::uint64_t key) const {
  const double parent = side(int(key >> 48) - 2);
  return {double(key & 0xffff) * parent, double((key >> 16) & 0xffff) * parent, double((key >> 32) & 0xffff) * parent};
}

std::uint64_t* FreeVoxels::coarse_mask(const Cell& cell, int coarse) {
  return &masks_[cell.first + std::uint32_t(rank_of(cell.listed, coarse))];
}

// Removes an emptied coarse cube from its cell's array (the cell's later ones move up).
void FreeVoxels::drop_coarse(Cell& cell, int coarse) {
  const auto at = masks_.begin() + std::ptrdiff_t(cell.first) + rank_of(cell.listed, coarse);
  const auto end = masks_.begin() + std::ptrdiff_t(cell.first) + bit_count(cell.listed);
  std::copy(at + 1, end, at);
  cell.listed &= ~(std::uint64_t(1) << coarse);
}

void FreeVoxels::add_cell(std::size_t cell, std::span<const Vec3> near) {
  // The centres that may cover a voxel of the cell; the coarse cubes one of
  // them covers whole are left out at once. (At most ~30: the centres are a
  // diameter apart; any further ones are left out, which only keeps more
  // voxels listed.)
  SphereOverCell spheres[64];
  std::size_t k = 0;
  std::uint64_t covered = 0;
  for (const Vec3& r : near) {
    if (k == std::size(spheres)) break;
    if (!reaches_cube(r, {0, 0, 0}, w_)) continue;
    spheres[k] = SphereOverCell(r, side(kVoxelLevel));
    if (spheres[k].reached_coarse() == 0) continue;
    covered |= spheres[k].covered_coarse();
    ++k;
  }
  // The voxels of the other coarse cubes, less those one sphere covers.
  const std::uint64_t open = ~covered;
  std::uint64_t mask[64];
  for (std::uint64_t m = open; m != 0; m &= m - 1) mask[std::countr_zero(m)] = ~std::uint64_t(0);
  for (std::size_t j = 0; j < k; ++j) {
    const std::uint64_t cubes = spheres[j].reached_coarse() & open;
    if (cubes == 0) continue;
    spheres[j].look_into(cubes);
    for (std::uint64_t m = cubes; m != 0; m &= m - 1) {
      const int b = std::countr_zero(m);
      mask[b] &= ~spheres[j].covered_voxels(b);
    }
  }
  Cell& c = cells_[cell];
  c.first = std::uint32_t(masks_.size());
  for (std::uint64_t m = open; m != 0; m &= m - 1) {
    const int b = std::countr_zero(m);
    if (mask[b] == 0) continue;
    masks_.push_back(mask[b]);
    c.listed |= std::uint64_t(1) << b;
    c.weight += weight_of(mask[b], kVoxelLevel);
  }
}

void FreeVoxels::start_sampling() {
  tree_.build(cells_.size(), [&](std::size_t c) { return cells_[c].weight; });
}

void FreeVoxels::add_weight(std::size_t cell, std::int64_t delta) {
  cells_[cell].weight += std::uint64_t(delta);
  tree_.add(cell, delta);
}

// The cell holding the r-th unit of weight; r becomes the rest within it.
std::size_t FreeVoxels::find_cell(std::uint64_t& r) const {
  std::size_t c = tree_.find_group(r) * WeightTree::kGroup;
  while (r >= cells_[c].weight) r -= cells_[c++].weight;
  return c;
}

FreeVoxels::Voxel FreeVoxels::draw(Random& rng) const {
  std::uint64_t r = uniform_below(rng, tree_.total());
  const std::size_t c = find_cell(r);
  const Cell& cell = cells_[c];
  Voxel v{c, -1, 0, 0, kVoxelLevel, {0, 0, 0}, side(kVoxelLevel)};
  std::uint64_t mask = 0;
  const std::uint64_t* m = masks_.data() + cell.first;
  for (std::uint64_t listed = cell.listed; listed != 0; listed &= listed - 1, ++m) {
    const std::uint64_t w = weight_of(*m, kVoxelLevel);
    if (r < w) {
      v.coarse = std::countr_zero(listed);
      mask = *m;
      v.lo = sub_cube_corner({0, 0, 0}, v.coarse, side(kCoarseLevel));
      break;
    }
    r -= w;
  }
  if (mask == 0) {
    for (v.brick = cell.bricks;; v.brick = bricks_[std::size_t(v.brick)].next) {
      const Brick& b = bricks_[std::size_t(v.brick)];
      const std::uint64_t w = weight_of(b.mask, int(b.key >> 48));
      if (r < w) break;
      r -= w;
    }
    const Brick& b = bricks_[std::size_t(v.brick)];
    mask = b.mask;
    v.level = int(b.key >> 48);
    v.side = side(v.level);
    v.lo = brick_corner(b.key);
  }
  v.bit = nth_set_bit(mask, r >> shift(v.level));
  v.lo = sub_cube_corner(v.lo, v.bit, v.side);
  return v;
}

void FreeVoxels::cover(std::span<const std::size_t> cells, std::span<const Vec3> r) {
  // The cells are scattered in memory: fetch them all before the work.
  for (const std::size_t c : cells) __builtin_prefetch(&cells_[c]);
  for (std::size_t k = 0; k < cells.size(); ++k)
    if (reaches_cube(r[k], {0, 0, 0}, w_)) __builtin_prefetch(&masks_[cells_[cells[k]].first]);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (!reaches_cube(r[k], {0, 0, 0}, w_)) continue;
    const std::int64_t delta = cover_cell(cells_[cells[k]], r[k]);
    if (delta != 0) add_weight(cells[k], delta);
  }
}

// Removes one cell's voxels covered by the sphere at r; returns the weight change.
std::int64_t FreeVoxels::cover_cell(Cell& cell, const Vec3& r) {
  std::int64_t delta = 0;
  if (cell.listed != 0) {
    SphereOverCell sphere(r, side(kVoxelLevel));
    const std::uint64_t cubes = sphere.reached_coarse() & cell.listed;
    if (cubes != 0) sphere.look_into(cubes);
    for (std::uint64_t hit = cubes; hit != 0; hit &= hit - 1) {
      const int b = std::countr_zero(hit);
      std::uint64_t* m = coarse_mask(cell, b);
      const std::uint64_t left = *m & ~sphere.covered_voxels(b);
      delta -= std::int64_t(weight_of(*m ^ left, kVoxelLevel));
      *m = left;
      if (left == 0) drop_coarse(cell, b);
    }
  }
  for (std::int32_t id = cell.bricks; id >= 0;) {
    Brick& b = bricks_[std::size_t(id)];
    const std::int32_t next = b.next;
    const int level = int(b.key >> 48);
    const Vec3 lo = brick_corner(b.key);
    if (reaches_cube(r, lo, 4 * side(level))) {
      const std::uint64_t left = b.mask & ~covered_sub_cubes(minus(r, lo), side(level));
      delta -= std::int64_t(weight_of(b.mask ^ left, level));
      b.mask = left;
      if (left == 0) drop_brick(cell, id);
    }
    id = next;
  }
  return delta;
}

void FreeVoxels::refine(const Voxel& v, std::span<const Vec3> near) {
  const bool deepest = v.level + 2 > finest_;
  std::uint64_t sub = ~std::uint64_t(0);  // its sub-voxels that no single sphere covers
  reaching_.clear();
  for (const Vec3& r : near) {
    if (!reaches_cube(r, v.lo, v.side)) continue;
    if (covers_cube(r, v.lo, v.side)) {
      sub = 0;
      break;
    }
    if (!deepest) sub &= ~covered_sub_cubes(minus(r, v.lo), v.side / 4);
    reaching_.push_back(r);
  }
  // The finest voxels cannot be refined: the exact test decides whether
  // any free point is left in them.
  if (sub != 0 && deepest && holds_free_point(v.lo, v.side, reaching_)) return;
  if (deepest) sub = 0;
  Cell& cell = cells_[v.cell];
  std::int64_t delta = -std::int64_t(std::uint64_t(1) << shift(v.level));
  const std::uint64_t bit = std::uint64_t(1) << v.bit;
  if (v.brick < 0) {
    std::uint64_t* m = coarse_mask(cell, v.coarse);
    if ((*m &= ~bit) == 0) drop_coarse(cell, v.coarse);
  } else if ((bricks_[std::size_t(v.brick)].mask &= ~bit) == 0) {
    drop_brick(cell, v.brick);
  }
  if (sub != 0) {
    const auto coord = [&](double u) { return std::uint64_t(std::llround(u / v.side)); };
    const std::uint64_t key = std::uint64_t(v.level + 2) << 48 | coord(v.lo.x) | coord(v.lo.y) << 16 | coord(v.lo.z) << 32;
    cell.bricks = new_brick({sub, key, cell.bricks});
    delta += std::int64_t(weight_of(sub, v.level + 2));
  }
  add_weight(v.cell, delta);
}

std::int32_t FreeVoxels::new_brick(const Brick& b) {
  if (unused_bricks_.empty()) {
    bricks_.push_back(b);
    return std::int32_t(bricks_.size() - 1);
  }
  const std::int32_t id = unused_bricks_.back();
  unused_bricks_.pop_back();
  bricks_[std::size_t(id)] = b;
  return id;
}

void FreeVoxels::drop_brick(Cell& cell, std::int32_t id) {
  std::int32_t* link = &cell.bricks;
  while (*link != id) link = &bricks_[std::size_t(*link)].next;
  *link = bricks_[std::size_t(id)].next;
  unused_bricks_.push_back(id);
}

std::size_t FreeVoxels::bytes() const {
  return cells_.capacity() * sizeof(Cell) + masks_.capacity() * sizeof(std::uint64_t) +
         bricks_.capacity() * sizeof(Brick) + unused_bricks_.capacity() * sizeof(std::int32_t) +
         cells_.size() / WeightTree::kGroup * sizeof(std::uint64_t);
}

}  // namespace coolgas
