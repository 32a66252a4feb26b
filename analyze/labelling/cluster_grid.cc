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
constexpr int kMaxPerSide[4] = {0, 2147483583, 40000, 1250};  // by d
}  // namespace

ClusterGrid::ClusterGrid(double L, Geometry g) : L_(L), geo_(g) {
  const int max_per_side = kMaxPerSide[g.d()];
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

std::string cluster_cells_text(Geometry g) {
  static const char* const kCells[4] = {
      "", "floor(L) segments of length L/floor(L); left and right neighbours; periodic",
      "floor(L)^2 square cells of side L/floor(L); edge neighbours; periodic",
      "floor(L)^3 cubic cells of side L/floor(L); face neighbours; periodic"};
  return kCells[g.d()];
}

ClusterGrid cluster_grid_of_dump(double L, const std::string& path, std::size_t dump, Geometry g) {
  try {
    return ClusterGrid(L, g);
  } catch (const InputError& e) {
    throw InputError(path + ": dump " + std::to_string(dump) + ": " + e.what());
  }
}

}  // namespace coolgas
