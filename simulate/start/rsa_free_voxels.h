// The voxels of random sequential addition (Zhang & Torquato, PRE 88,
// 053312, 2013): cubes whose union holds all the space still free (farther
// than one diameter from every centre placed), drawn with probability
// proportional to their volume.
//
// Each cell of the centre grid (side w) is cut into 4x4x4 coarse cubes of
// side w/4, each of those into 4x4x4 voxels of side w/16: a coarse cube is a
// 64-bit mask of its voxels still listed, and a cell keeps only its coarse
// cubes with a voxel left, in one array. A voxel refined after a failed
// trial becomes a brick, the mask of its own 4x4x4 sub-voxels two levels
// down. A voxel leaves as soon as one exclusion sphere covers it whole: at
// the build, when a sphere is placed next to it (cover), or when a trial in
// it fails and a sphere around it covers it (refine). The union of the
// listed voxels thus always holds all the free space.
//
// A voxel's weight is its volume in units of the finest voxel, 8^(finest -
// level); cells are drawn by weight (rsa_weight_tree.h).
#pragma once
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "simulate/engine/cell_grid.h"
#include "simulate/engine/particles.h"
#include "common/random.h"
#include "simulate/start/rsa_sub_cubes.h"
#include "simulate/start/rsa_weight_tree.h"

namespace coolgas {

class FreeVoxels {
 public:
  // The cells of the centre grid: n^3 of side w.
  FreeVoxels(int cells_per_side, double cell_width);

  // Lists the voxels of every cell from the centres placed so far:
  // centres(f) calls f(cx, cy, cz, offset) for each, with the coordinates of
  // its cell and its offset from the cell's corner, cell by cell. Each centre
  // is seen from the 27 cells around its own, in two passes: the coarse cubes
  // covered whole, then the voxels of the others.
  template <class ForEachCentre>
  void build(ForEachCentre&& centres);

  struct Voxel {
    std::size_t cell;
    std::int32_t brick;  // -1: a voxel of a coarse cube, else the brick holding it
    int coarse;          // the coarse cube (brick < 0)
    int bit;             // in the mask
    int level;           // side = cell width / 2^level
    Vec3 lo;             // corner, relative to the cell's corner
    double side;
  };

  bool empty() const { return tree_.total() == 0; }
  // A voxel with probability proportional to its volume (not empty()).
  Voxel draw(Random& rng) const;

  // The next draw most likely takes the number a copy of the generator
  // gives now and lands where that number lands now (one trial changes the
  // weights little). Asking the memory for what it will read, one step at a
  // time while the current trial is tested and applied, hides most of the
  // draw's latency; a wrong guess costs only the fetches. Steps: guess()
  // fetches the page's group sums, then narrow() the group's cells, then
  // land() the cell's masks and returns the cell (or -1: no guess).
  struct Guess {
    std::uint64_t r;
    std::size_t page, group;
    bool valid;
  };
  Guess guess(const Random& rng) const;
  void narrow(Guess& g) const;
  std::int64_t land(Guess& g) const;

  // Removes the voxels that the exclusion sphere (radius 1) of a newly placed
  // centre covers whole, in the 27 cells around its own: cell (cx, cy, cz),
  // offset from the cell's corner.
  void cover(int cx, int cy, int cz, const Vec3& offset);
  // After a failed trial in v: removes v if one of the centres `near` (all
  // those within reach, relative to v's cell corner, to ~1e-7) covers it,
  // else replaces it by its sub-voxels two levels down that none of them
  // covers. A voxel of the finest level cannot be refined: then refine()
  // returns false and the caller settles it with the exact positions.
  bool refine(const Voxel& v, std::span<const Vec3> near);
  // A finest voxel left by refine(): dropped unless it still holds a free
  // point, by the exact test (rsa_free_point.h) on the exact positions of
  // the centres near it.
  void settle(const Voxel& v, std::span<const Vec3> exact_near);

 private:
  static constexpr int kCoarseLevel = 2, kVoxelLevel = 4;
  struct Cell {
    std::uint64_t weight = 0;  // total weight of its voxels
    std::uint64_t listed = 0;  // which coarse cubes have voxels listed
    std::uint32_t first = 0;   // where their masks start in masks_, in cube order
    std::int32_t bricks = -1;  // first brick, -1 if none
  };
  struct Brick {
    std::uint64_t mask;
    std::uint64_t key;  // level of its sub-voxels << 48 | the refined voxel's x, y, z (16 bits each)
    std::int32_t next;  // next brick of the same cell, -1 at the end
  };

  // The 3 views along each axis of a centre at `offset` in its cell, from
  // the cells at -1, 0, +1 along that axis.
  struct Views {
    AxisView axis[3][3];
  };
  Views views_of(const Vec3& offset, bool voxels) const;
  // The sphere as the neighbour cell at offset o (each -1..1) sees it.
  static SphereOverCell sphere_over(const Views& v, const CellCoord& o) {
    return {v.axis[0][o.x + 1], v.axis[1][o.y + 1], v.axis[2][o.z + 1]};
  }
  void mark_covered_coarse(int cx, int cy, int cz, const Vec3& offset);
  void open_slabs();
  std::uint64_t* slab_masks(int slab);
  void mark_covered_voxels(int cx, int cy, int cz, const Vec3& offset);
  void close_slabs(int done);
  void close_slab(int slab);
  double side(int level) const { return sides_[level]; }
  int shift(int level) const { return 3 * (finest_ - level); }
  std::uint64_t weight_of(std::uint64_t mask, int level) const;
  Vec3 brick_corner(std::uint64_t key) const;
  std::uint64_t* coarse_mask(const Cell& cell, int coarse);
  void drop_coarse(Cell& cell, std::uint64_t emptied);
  std::int64_t cover_cell(std::size_t c, Cell& cell, const SphereOverCell& s, std::uint64_t cubes, const Vec3& r);

  std::int32_t new_brick(const Brick& b);
  void drop_brick(std::size_t c, Cell& cell, std::int32_t id);
  void add_weight(std::size_t cell, std::int64_t delta);
  std::size_t find_cell(std::uint64_t& r) const;

  int n_;
  double w_;
  int finest_;  // the finest level: the weights of all cells sum below 2^62
  double sides_[17];  // w / 2^level
  std::vector<Cell> cells_;
  std::vector<std::uint64_t> brick_cells_;  // a bit per cell: it has bricks
  // The coarse cubes' masks, by cell then cube, in one block: reserved for
  // every coarse cube no sphere covers whole (its pages untouched), filled
  // slab by slab with those that kept a voxel (three quarters), then shrunk.
  class Masks {
   public:
    Masks() = default;
    Masks(const Masks&) = delete;
    Masks& operator=(const Masks&) = delete;
    ~Masks() { std::free(data_); }
    void reserve(std::size_t capacity);  // pages untouched until written
    void push_back(std::uint64_t m) { data_[size_++] = m; }
    void shrink_to_size();
    std::uint64_t* data() { return data_; }
    const std::uint64_t* data() const { return data_; }
    std::uint64_t& operator[](std::size_t i) { return data_[i]; }
    std::size_t size() const { return size_; }

   private:
    std::uint64_t* data_ = nullptr;
    std::size_t size_ = 0;
  };
  Masks masks_;
  // During the build: per slab of cells (z), the masks of its open coarse
  // cubes (Cell::first indexing into them), and which slabs are complete.
  std::vector<std::vector<std::uint64_t>> slab_masks_;
  std::vector<std::size_t> slab_size_;
  std::vector<bool> slab_closed_;
  std::vector<Brick> bricks_;
  std::vector<std::int32_t> unused_bricks_;
  WeightTree tree_;
  std::vector<Vec3> reaching_;  // scratch
  void remove(const Voxel& v, std::uint64_t sub);
};

template <class ForEachCentre>
void FreeVoxels::build(ForEachCentre&& centres) {
  // Pass 1: the coarse cubes one sphere covers whole (kept in Cell::listed).
  centres([&](int cx, int cy, int cz, const Vec3& offset) { mark_covered_coarse(cx, cy, cz, offset); });
  open_slabs();
  // Pass 2: every voxel of the other coarse cubes, less those one sphere
  // covers whole. The centres come slab by slab (z); a slab of cells is
  // complete once the centres of the slabs on both sides are done, and is
  // then moved into masks_ without its emptied masks, so that only a few
  // slabs are ever held with all their masks.
  int done = 0;  // the centres of slabs [0, done) are done
  centres([&](int cx, int cy, int cz, const Vec3& offset) {
    if (cz > done) close_slabs(done = cz);
    mark_covered_voxels(cx, cy, cz, offset);
  });
  close_slabs(n_ + 2);
  tree_.build(cells_.size(), [&](std::size_t c) { return cells_[c].weight; });
}

}  // namespace coolgas
