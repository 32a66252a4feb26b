#include "simulate/start/rsa_free_voxels.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <new>
#include <stdexcept>

#include "simulate/start/rsa_free_point.h"
#include "simulate/start/rsa_sub_cubes.h"

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

void FreeVoxels::Masks::reserve(std::size_t capacity) {
  std::free(data_);
  data_ = static_cast<std::uint64_t*>(std::malloc(std::max<std::size_t>(capacity, 1) * sizeof(std::uint64_t)));
  if (data_ == nullptr) throw std::bad_alloc();
  size_ = 0;
}

void FreeVoxels::Masks::shrink_to_size() {
  if (void* smaller = std::realloc(data_, std::max<std::size_t>(size_, 1) * sizeof(std::uint64_t)))
    data_ = static_cast<std::uint64_t*>(smaller);
}

FreeVoxels::FreeVoxels(int cells_per_side, double cell_width)
    : n_(cells_per_side),
      w_(cell_width),
      cells_(std::size_t(n_) * std::size_t(n_) * std::size_t(n_)),
      brick_cells_(cells_.size() / 64 + 1),
      tree_(cells_.size()) {
  // A whole cell weighs 8^finest; bricks refine two levels at a time from level 4.
  finest_ = std::min(16, ((62 - int(std::bit_width(cells_.size()))) / 3) & ~1);
  for (int level = 0; level < int(std::size(sides_)); ++level) sides_[level] = std::ldexp(w_, -level);
}

FreeVoxels::Views FreeVoxels::views_of(const Vec3& offset, bool voxels) const {
  Views v;
  for (int d = 0; d < 3; ++d)
    for (int k = 0; k < 3; ++k) v.axis[d][k] = AxisView(offset[d] - (k - 1) * w_, side(kVoxelLevel), voxels);
  return v;
}


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

// Removes emptied coarse cubes from their cell's array, the others moving up.
void FreeVoxels::drop_coarse(Cell& cell, std::uint64_t emptied) {
  std::uint64_t* const m = masks_.data() + cell.first;
  int to = 0, from = 0;
  for (std::uint64_t listed = cell.listed; listed != 0; listed &= listed - 1, ++from)
    if (!(emptied >> std::countr_zero(listed) & 1)) m[to++] = m[from];
  cell.listed &= ~emptied;
}

void FreeVoxels::mark_covered_coarse(int cx, int cy, int cz, const Vec3& offset) {
  const Views v = views_of(offset, false);
  for_each_neighbour_cell(n_, 0.0, {cx, cy, cz}, [&](const NeighbourCell& nb) {
    const SphereOverCell s = sphere_over(v, nb.offset);
    if (!s.may_cover_coarse()) return;
    const std::uint64_t covered = s.covered_coarse();
    if (covered != 0) cells_[std::size_t(nb.index)].listed |= covered;
  });
}

// After pass 1: the open coarse cubes are the others; each cell's index
// into its slab's masks, and room for all of them in masks_.
void FreeVoxels::open_slabs() {
  const std::size_t per_slab = std::size_t(n_) * std::size_t(n_);
  slab_masks_.assign(std::size_t(n_), {});
  slab_size_.assign(std::size_t(n_), 0);
  slab_closed_.assign(std::size_t(n_), false);
  std::size_t total = 0;
  for (std::size_t c = 0; c < cells_.size(); ++c) {
    Cell& cell = cells_[c];
    cell.listed = ~cell.listed;
    std::size_t& size = slab_size_[c / per_slab];
    cell.first = std::uint32_t(size);
    size += std::size_t(bit_count(cell.listed));
  }
  for (const std::size_t size : slab_size_) total += size;
  if (total > UINT32_MAX) throw std::length_error("random sequential addition: too many cells for the voxel masks");
  masks_.reserve(total);
}

// A slab's masks, every voxel listed until a sphere covers it (set up when
// first asked for, one mask more so that a slab without any is set up too).
std::uint64_t* FreeVoxels::slab_masks(int slab) {
  std::vector<std::uint64_t>& m = slab_masks_[std::size_t(slab)];
  if (m.empty()) m.assign(slab_size_[std::size_t(slab)] + 1, ~std::uint64_t(0));
  return m.data();
}

void FreeVoxels::mark_covered_voxels(int cx, int cy, int cz, const Vec3& offset) {
  const Views v = views_of(offset, true);
  for_each_neighbour_cell(n_, 0.0, {cx, cy, cz}, [&](const NeighbourCell& nb) {
    std::uint64_t* const masks = slab_masks(nb.cell.z);  // asked for even if untouched: the slab is set up
    const SphereOverCell s = sphere_over(v, nb.offset);
    if (!s.may_cover_voxel()) return;
    const std::uint64_t covering = s.covering_coarse();
    if (covering == 0) return;
    const Cell& c = cells_[std::size_t(nb.index)];
    for (std::uint64_t m = covering & c.listed; m != 0; m &= m - 1) {
      const int b = std::countr_zero(m);
      masks[c.first + std::uint32_t(rank_of(c.listed, b))] &= ~s.covered_voxels(b);
    }
  });
}

// The centres of slabs [0, done) are done: slab s of cells, reached by the
// centres of slabs s - 1, s and s + 1, is complete once s + 1 < done. The
// box is periodic, so slab 0 also waits for the last slab of centres, and
// the last slab of cells for the first: those close at the end (done > n).
void FreeVoxels::close_slabs(int done) {
  for (int slab = 0; slab < n_; ++slab)
    if (!slab_closed_[std::size_t(slab)] && (done > n_ || (slab >= 1 && slab + 1 < done))) close_slab(slab);
  if (done > n_) masks_.shrink_to_size();
}

// Moves a complete slab's masks into masks_, less the emptied ones, and sets its cells' weights.
void FreeVoxels::close_slab(int slab) {
  const std::size_t per_slab = std::size_t(n_) * std::size_t(n_);
  const std::uint64_t* const from = slab_masks(slab);
  for (std::size_t c = std::size_t(slab) * per_slab; c < std::size_t(slab + 1) * per_slab; ++c) {
    Cell& cell = cells_[c];
    const std::uint64_t open = cell.listed;
    const std::size_t first = cell.first;
    cell.listed = 0;
    cell.first = std::uint32_t(masks_.size());
    cell.weight = 0;
    std::size_t k = 0;
    for (std::uint64_t m = open; m != 0; m &= m - 1, ++k) {
      const std::uint64_t mask = from[first + k];
      if (mask == 0) continue;
      masks_.push_back(mask);
      cell.listed |= std::uint64_t(1) << std::countr_zero(m);
      cell.weight += weight_of(mask, kVoxelLevel);
    }
  }
  std::vector<std::uint64_t>().swap(slab_masks_[std::size_t(slab)]);
  slab_closed_[std::size_t(slab)] = true;
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

FreeVoxels::Guess FreeVoxels::guess(const Random& rng) const {
  if (empty()) return {0, 0, 0, false};
  Random copy = rng;
  Guess g{uniform_below(copy, tree_.total()), 0, 0, false};
  g.page = tree_.find_page(g.r);
  tree_.prefetch_page(g.page);
  g.valid = true;
  return g;
}

void FreeVoxels::narrow(Guess& g) const {
  if (!g.valid) return;
  g.group = tree_.find_group_in(g.page, g.r);
  const Cell* c = &cells_[g.group * WeightTree::kGroup];
  for (std::size_t k = 0; k < WeightTree::kGroup * sizeof(Cell); k += 64) __builtin_prefetch(reinterpret_cast<const char*>(c) + k);
}

std::int64_t FreeVoxels::land(Guess& g) const {
  if (!g.valid) return -1;
  std::size_t c = g.group * WeightTree::kGroup;
  const std::size_t end = std::min(c + WeightTree::kGroup, cells_.size());
  while (c < end && g.r >= cells_[c].weight) g.r -= cells_[c++].weight;
  if (c == end) return -1;
  __builtin_prefetch(masks_.data() + cells_[c].first);
  return std::int64_t(c);
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

void FreeVoxels::cover(int cx, int cy, int cz, const Vec3& offset) {
  // The cells are scattered in memory: first, from the views alone, which
  // of the 27 the sphere covers a voxel of (or which hold bricks), then
  // their records and masks all asked for at once, then the work.
  const Views v = views_of(offset, true);
  CellCoord active[27];
  std::size_t cells[27];
  std::uint64_t covering[27];
  int n = 0;
  for_each_neighbour_cell(n_, 0.0, {cx, cy, cz}, [&](const NeighbourCell& nb) {
    const SphereOverCell s = sphere_over(v, nb.offset);
    const auto c = std::size_t(nb.index);
    const std::uint64_t cubes = s.may_cover_voxel() ? s.covering_coarse() : 0;
    if (cubes == 0 && !(brick_cells_[c >> 6] >> (c & 63) & 1)) return;
    active[n] = nb.offset;
    cells[n] = c;
    covering[n++] = cubes;
    __builtin_prefetch(&cells_[c]);
  });
  for (int j = 0; j < n; ++j) {
    const std::uint64_t* m = masks_.data() + cells_[cells[j]].first;
    __builtin_prefetch(m);
    __builtin_prefetch(m + 8);
  }
  for (int j = 0; j < n; ++j) {
    const CellCoord o = active[j];
    const SphereOverCell s = sphere_over(v, o);
    Cell& cell = cells_[cells[j]];
    const Vec3 r{offset.x - o.x * w_, offset.y - o.y * w_, offset.z - o.z * w_};
    const std::int64_t delta = cover_cell(cells[j], cell, s, covering[j] & cell.listed, r);
    if (delta != 0) add_weight(cells[j], delta);
  }
}

// Removes one cell's voxels covered by the sphere seen as s, at r from the
// cell's corner, in the given coarse cubes and the bricks; returns the weight change.
std::int64_t FreeVoxels::cover_cell(std::size_t c, Cell& cell, const SphereOverCell& s, std::uint64_t cubes, const Vec3& r) {
  std::int64_t delta = 0;
  std::uint64_t emptied = 0;
  for (std::uint64_t hit = cubes; hit != 0; hit &= hit - 1) {
    const int b = std::countr_zero(hit);
    std::uint64_t* m = coarse_mask(cell, b);
    const std::uint64_t left = *m & ~s.covered_voxels(b);
    delta -= std::int64_t(weight_of(*m ^ left, kVoxelLevel));
    *m = left;
    if (left == 0) emptied |= std::uint64_t(1) << b;
  }
  if (emptied != 0) drop_coarse(cell, emptied);
  for (std::int32_t id = cell.bricks; id >= 0;) {
    Brick& b = bricks_[std::size_t(id)];
    const std::int32_t next = b.next;
    const int level = int(b.key >> 48);
    const Vec3 lo = brick_corner(b.key);
    if (reaches_cube(r, lo, 4 * side(level))) {
      const std::uint64_t left = b.mask & ~covered_sub_cubes(minus(r, lo), side(level));
      delta -= std::int64_t(weight_of(b.mask ^ left, level));
      b.mask = left;
      if (left == 0) drop_brick(c, cell, id);
    }
    id = next;
  }
  return delta;
}

bool FreeVoxels::refine(const Voxel& v, std::span<const Vec3> near) {
  const bool deepest = v.level + 2 > finest_;
  std::uint64_t sub = ~std::uint64_t(0);  // its sub-voxels that no single sphere covers
  for (const Vec3& r : near) {
    if (!reaches_cube(r, v.lo, v.side)) continue;
    if (covers_cube(r, v.lo, v.side)) {
      sub = 0;
      break;
    }
    if (!deepest) sub &= ~covered_sub_cubes(minus(r, v.lo), v.side / 4);
  }
  if (sub != 0 && deepest) return false;
  remove(v, sub);
  return true;
}

void FreeVoxels::settle(const Voxel& v, std::span<const Vec3> exact_near) {
  reaching_.clear();
  for (const Vec3& r : exact_near)
    if (reaches_cube(r, v.lo, v.side)) reaching_.push_back(r);
  if (!holds_free_point(v.lo, v.side, reaching_)) remove(v, 0);
}

// Takes v out, and puts in its place the sub-voxels in `sub` (a brick two levels down).
void FreeVoxels::remove(const Voxel& v, std::uint64_t sub) {
  Cell& cell = cells_[v.cell];
  std::int64_t delta = -std::int64_t(std::uint64_t(1) << shift(v.level));
  const std::uint64_t bit = std::uint64_t(1) << v.bit;
  if (v.brick < 0) {
    std::uint64_t* m = coarse_mask(cell, v.coarse);
    if ((*m &= ~bit) == 0) drop_coarse(cell, std::uint64_t(1) << v.coarse);
  } else if ((bricks_[std::size_t(v.brick)].mask &= ~bit) == 0) {
    drop_brick(v.cell, cell, v.brick);
  }
  if (sub != 0) {
    const auto coord = [&](double u) { return std::uint64_t(std::llround(u / v.side)); };
    const std::uint64_t key = std::uint64_t(v.level + 2) << 48 | coord(v.lo.x) | coord(v.lo.y) << 16 | coord(v.lo.z) << 32;
    cell.bricks = new_brick({sub, key, cell.bricks});
    brick_cells_[v.cell >> 6] |= std::uint64_t(1) << (v.cell & 63);
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

void FreeVoxels::drop_brick(std::size_t c, Cell& cell, std::int32_t id) {
  std::int32_t* link = &cell.bricks;
  while (*link != id) link = &bricks_[std::size_t(*link)].next;
  *link = bricks_[std::size_t(id)].next;
  unused_bricks_.push_back(id);
  if (cell.bricks < 0) brick_cells_[c >> 6] &= ~(std::uint64_t(1) << (c & 63));
}

}  // namespace coolgas
