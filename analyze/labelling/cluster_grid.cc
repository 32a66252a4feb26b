#include "analyze/labelling/cluster_grid.h"

#include <string>

#include "common/error.h"
#include "common/tsv.h"

namespace coolgas {

namespace {
// Run numbers and masses are int32 (cluster_labeller.h): fewer than 2^31 cells.
constexpr int kMaxPerSide = 1250;
}  // namespace

ClusterGrid::ClusterGrid(double L) : L_(L) {
  if (!std::isfinite(L) || L < 1)
    throw InputError("box side L = " + format_number(L) + " is too small for unit cluster cells: need L >= 1");
  if (L >= kMaxPerSide + 1)
    throw InputError("box side L = " + format_number(L) +
                     " is too large for the cluster labeller's 32-bit run numbers: need L < " +
                     std::to_string(kMaxPerSide + 1));
  n_ = static_cast<int>(std::floor(L));
  width_ = L / n_;
  inv_width_ = 1.0 / width_;
  last_ = n_ - 1;
}

ClusterGrid cluster_grid_of_dump(double L, const std::string& path, std::size_t dump) {
  try {
    return ClusterGrid(L);
  } catch (const InputError& e) {
    throw InputError(path + ": dump " + std::to_string(dump) + ": " + e.what());
  }
}

}  // namespace coolgas
