#include "simulate/engine/cell_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "common/limits.h"
#include "common/tsv.h"

namespace coolgas {

namespace {
// Cells are made a hair wider than the diameter so that two touching spheres
// are never two cells apart, even with positions rounded at the last digit.
constexpr double kWidthMargin = 1.0 + 1e-9;

// The head blocks: 4 cells along x, 2 along y and z, 16 heads of 4 bytes, one
// cache line (in 2D, 4 along x and y; in 1D, 16 along x). A block's cells
// are x fastest, then y, then z; blocks are in the same order, over sides
// padded to whole blocks. kBlockCells[d] is a block's cells along x, y, z.
constexpr int kHeadBlock = 16;
constexpr int kBlockCells[4][3] = {{}, {16, 1, 1}, {4, 4, 1}, {4, 2, 2}};

int blocks(int n, int width) { return (n + width - 1) / width; }

// slot()'s term of coordinate u along an axis with blocks `width` wide, of
// which the block index is worth `block_step` slots and the place within a
// block `cell_step`.
std::vector<std::int32_t> slot_terms(int n, int width, std::int64_t block_step, int cell_step) {
  std::vector<std::int32_t> t(static_cast<std::size_t>(n));
  for (int u = 0; u < n; ++u) t[std::size_t(u)] = std::int32_t((u / width) * block_step + (u % width) * cell_step);
  return t;
}
}  // namespace

namespace {

bool fits_grid(double L, double min_width) { return std::floor(L / (min_width * kWidthMargin)) >= 3; }

// The smallest box side that fits_grid, exactly: 3 w (1 + 1e-9) rounded may
// land an ulp or two either side of it (a few steps; bounded, so that a
// width that is not a number cannot loop).
double smallest_box(double min_width) {
  double L = 3 * min_width * kWidthMargin;
  for (int i = 0; i < 64 && !fits_grid(L, min_width); ++i) L = std::nextafter(L, INFINITY);
  for (int i = 0; i < 64 && fits_grid(std::nextafter(L, 0.0), min_width); ++i) L = std::nextafter(L, 0.0);
  return L;
}

}  // namespace

// Both numbers in their shortest exact form, the limit the exact one
// enforced: rounded to six digits, the limit (a hair above 3, kWidthMargin)
// read "L >= 3" in the refusal of L = 3.
std::string check_box_fits_grid(double L, double min_width) {
  if (fits_grid(L, min_width)) return "";
  return "box side L = " + format_number(L) + " is too small: the cell grid needs L >= " +
         format_number(smallest_box(min_width)) + " (three cells, each a hair wider than " +
         format_number(min_width) + "); use more particles or a lower phi";
}

std::int64_t CellGrid::cells_for(double L, double min_width, Geometry g) {
  if (!(std::isfinite(L) && min_width > 0) || !check_box_fits_grid(L, min_width).empty()) return 0;
  const double cells = g.power(std::floor(L / (min_width * kWidthMargin)));  // exact below 2^53
  return cells > double(kMaxIndex32) ? -1 : std::int64_t(cells);  // beyond 32-bit indices: no checkpoint can match
}

CellGrid::CellGrid(double L, double min_width, std::size_t n, Geometry g) {
  const std::string err = check_box_fits_grid(L, min_width);
  if (!err.empty()) throw std::invalid_argument(err);
  const double side = std::floor(L / (min_width * kWidthMargin));
  if (side > double(std::numeric_limits<std::int32_t>::max() - kHeadBlock))
    throw std::invalid_argument("the cell grid's cells do not fit 32-bit indices");
  n_ = static_cast<int>(side);
  layers_ = g.along(2, n_);
  inv_n_ = 1.0 / n_;
  w_ = L / n_;
  const int* block = kBlockCells[g.d()];
  const int block_x = block[0], block_y = block[1], block_z = block[2];
  const int rows = g.along(1, n_);
  const std::int64_t bx = blocks(n_, block_x), by = blocks(rows, block_y), bz = blocks(layers_, block_z);
  if (bx * by * bz * kHeadBlock > std::numeric_limits<std::int32_t>::max()) {
    std::ostringstream s;
    s << "the cell grid's " << n_ << "^" << g.d() << " cells do not fit 32-bit indices";
    throw std::invalid_argument(s.str());
  }
  slot_x_ = slot_terms(n_, block_x, kHeadBlock, 1);
  slot_y_ = slot_terms(rows, block_y, bx * kHeadBlock, block_x);
  slot_z_ = slot_terms(layers_, block_z, bx * by * kHeadBlock, block_x * block_y);
  head_.assign(static_cast<std::size_t>(bx * by * bz * kHeadBlock), -1);
  own_next_.assign(n, -1);
  next_ = own_next_.data();
  prev_.assign(n, -1);
  cell_.assign(n, -1);
}

int CellGrid::cell_of(double x, double y, double z) const {
  auto c = [this](double u, int n) { return std::clamp(static_cast<int>(std::floor(u / w_)), 0, n - 1); };
  return index({c(x, n_), c(y, rows()), c(z, layers_)});
}

void CellGrid::insert(int p, int cell) {
  std::int32_t& head = head_of(cell);
  cell_[p] = cell;
  prev_[p] = -1;
  link(p) = head;
  if (head >= 0) prev_[head] = p;
  head = p;
}

void CellGrid::remove(int p) {
  const int c = cell_[p];
  const int nxt = link(p);
  if (prev_[p] >= 0) link(prev_[p]) = nxt;
  else head_of(c) = nxt;
  if (nxt >= 0) prev_[nxt] = prev_[p];
  cell_[p] = -1;
}

CellExit first_cell_exit(const CellGrid& grid, int cell, const Vec3& r, const Vec3& v) {
  const double w = grid.width();
  const CellCoord c = grid.coord(cell);
  const int cc[3] = {c.x, c.y, c.z};
  CellExit exit{std::numeric_limits<double>::infinity(), -1};
  for (int d = 0; d < 3; ++d) {
    if (v[d] > 0) {
      const double t = std::max(0.0, ((cc[d] + 1) * w - r[d]) / v[d]);
      if (t < exit.time) exit = {t, 2 * d + 1};
    } else if (v[d] < 0) {
      const double t = std::max(0.0, (cc[d] * w - r[d]) / v[d]);
      if (t < exit.time) exit = {t, 2 * d};
    }
  }
  return exit;
}

int cell_across_face(const CellGrid& grid, int cell, int face, double L, Vec3& r, Image& image) {
  const int axis = face / 2;
  const bool up = face % 2 == 1;
  CellCoord c = grid.coord(cell);
  int* cd = axis == 0 ? &c.x : (axis == 1 ? &c.y : &c.z);
  const int n = grid.cells_per_side();
  if (up && ++*cd == n) {
    *cd = 0;
    r[axis] -= L;
    ++image[axis];
  } else if (!up && --*cd < 0) {
    *cd = n - 1;
    r[axis] += L;
    --image[axis];
  }
  return grid.index(c);
}

void CellGrid::clear() {
  std::fill(head_.begin(), head_.end(), -1);
  std::fill(cell_.begin(), cell_.end(), -1);
}

// Checkpoints hold the heads by plain cell index, as before the blocks.
void CellGrid::save(StateWriter& out, const std::string& prefix) const {
  std::vector<std::int32_t> heads(static_cast<std::size_t>(cell_count()));
  for (std::size_t c = 0; c < heads.size(); ++c) heads[c] = first(int(c));
  out.put(prefix + "heads", heads);
  out.put(prefix + "prev", prev_);
  out.put(prefix + "cell", cell_);
  out.put(prefix + "own_next", own_next_);
}

void CellGrid::load(const StateReader& in, const std::string& prefix) {
  auto same_size = [&](const std::vector<std::int32_t>& loaded, const std::vector<std::int32_t>& now, const char* what) {
    if (loaded.size() != now.size()) in.fail(prefix + what + " does not match the grid");
  };
  auto heads = in.get<std::int32_t>(prefix + "heads");
  auto prev = in.get<std::int32_t>(prefix + "prev");
  auto cell = in.get<std::int32_t>(prefix + "cell");
  auto own = in.get<std::int32_t>(prefix + "own_next");
  if (heads.size() != static_cast<std::size_t>(cell_count())) in.fail(prefix + "heads does not match the grid");
  same_size(prev, prev_, "prev");
  same_size(cell, cell_, "cell");
  same_size(own, own_next_, "own_next");
  for (std::size_t c = 0; c < heads.size(); ++c) head_of(int(c)) = heads[c];
  prev_ = std::move(prev);
  cell_ = std::move(cell);
  own_next_ = std::move(own);
  if (!own_next_.empty()) next_ = own_next_.data();
  check_lists(in, prefix);
}

// The lists of a checkpoint are walked by every later search and crossing:
// an index out of range there is a wild read or write, a loop an endless
// search. So they are checked once, here, in O(n + cells): each cell's list
// from its head, every link back and forth consistent, every particle with
// a cell met exactly once, in that cell's list.
void CellGrid::check_lists(const StateReader& in, const std::string& prefix) const {
  const auto n = std::int64_t(cell_.size());
  const auto particle = [&](std::int64_t p) { return p >= 0 && p < n; };
  std::int64_t listed = 0, met = 0;
  for (std::int64_t p = 0; p < n; ++p) {
    const std::int32_t c = cell_[std::size_t(p)];
    if (c < -1 || c >= cell_count())
      in.fail(prefix + "cell[" + std::to_string(p) + "] = " + std::to_string(c) + " is not a cell (0 to " +
              std::to_string(cell_count() - 1) + ", or -1)");
    listed += c >= 0;
  }
  for (int c = 0; c < cell_count(); ++c)
    for (std::int32_t p = first(c), before = -1; p != -1; before = p, p = next(p))
      if (!particle(p) || cell_[std::size_t(p)] != c || prev_[std::size_t(p)] != before || ++met > listed)
        in.fail(prefix + "the list of cell " + std::to_string(c) + " holds particle " + std::to_string(p) +
                " out of range or inconsistently");
  if (met != listed)
    in.fail(prefix + "the cell lists hold " + std::to_string(met) + " particles, the cells of " +
            std::to_string(listed) + " say they should");
}

}  // namespace coolgas
