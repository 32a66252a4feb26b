#include "analyze/labelling/cluster_grid.h"

#include <stdexcept>
#include <string>

#include "common/error.h"
#include "common/tsv.h"

namespace coolgas {

namespace {
// Run numbers and masses are int32 (cluster_labeller.h): fewer than 2^31
// cells; in 2D also the 32-bit bit index of a cell (cluster_occupancy.h),
// 64 ceil(n/64) n < 2^32; in 1D one row of fewer than 2^31 cells, n + 63
// (its words are (n + 63)/64) still an int.
constexpr int kMaxPerSide = 1250, kMaxPerSide2d = 40000, kMaxPerSide1d = 2147483583;
}  // namespace

ClusterGrid::ClusterGrid(double L, int dimension) : L_(L), dimension_(dimension) {
  if (dimension < 1 || dimension > 3) throw std::logic_error("a cluster grid has dimension 1, 2 or 3");
  const int max_per_side = dimension == 3 ? kMaxPerSide : dimension == 2 ? kMaxPerSide2d : kMaxPerSide1d;
  if (!std::isfinite(L) || L < 1)
    throw InputError("box side L = " + format_number(L) + " is too small for unit cluster cells: need L >= 1");
  if (L >= double(max_per_side) + 1)
    throw InputError("box side L = " + format_number(L) +
                     " is too large for the cluster labeller's 32-bit run numbers: need L < " +
                     std::to_string(std::int64_t(max_per_side) + 1));
  n_ = static_cast<int>(std::floor(L));
  width_ = L / n_;
  inv_width_ = 1.0 / width_;
  last_ = n_ - 1;
}

ClusterGrid cluster_grid_of_dump(double L, const std::string& path, std::size_t dump, int dimension) {
  try {
    return ClusterGrid(L, dimension);
  } catch (const InputError& e) {
    throw InputError(path + ": dump " + std::to_string(dump) + ": " + e.what());
  }
}

}  // namespace coolgas
