#include "analyze/snapshot/scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "common/error.h"
#include "common/tsv.h"

namespace coolgas {

namespace {

// Distinct colours readable on white (the "tab10" palette of matplotlib, grey left out).
constexpr std::array<std::uint32_t, 9> kPalette = {0x1f77b4, 0xd62728, 0x2ca02c, 0xff7f0e, 0x9467bd,
                                                   0x8c564b, 0xe377c2, 0x17becf, 0xbcbd22};

void check(const SnapshotOptions& o, double L) {
  if (o.colored < 0 || o.colored > palette_size())
    throw InputError("--colored must be between 0 and " + std::to_string(palette_size()) + ", got " +
                     std::to_string(o.colored));
  if (o.view == SnapshotView::kSlab && !(o.thickness > 0 && o.thickness <= L))
    throw InputError("--thickness must be in (0, L] = (0, " + format_number(L) + "], got " +
                     format_number(o.thickness));
  if (o.max_points < 1) throw InputError("--max-points must be >= 1, got " + std::to_string(o.max_points));
}

bool in_view(const SnapshotOptions& o, double L, double z) {
  return o.view == SnapshotView::k3d || std::abs(z - 0.5 * L) < 0.5 * o.thickness;
}

}  // namespace

int palette_size() { return static_cast<int>(kPalette.size()); }

std::uint32_t cluster_colour(int rank) {
  return rank >= 1 && rank <= palette_size() ? kPalette[rank - 1] : kOtherClusters;
}

SnapshotScene make_scene(const ClusterGrid& grid, std::span<const double> pos, const SnapshotOptions& opt) {
  const double L = grid.box();
  check(opt, L);
  ClusterLabeller lab;
  lab.label(grid, pos);
  const auto ranked = lab.ranked();
  SnapshotScene scene;
  std::vector<std::int32_t> ids;  // cluster ids of the coloured clusters, by rank
  for (int r = 0; r < opt.colored && r < int(ranked.size()); ++r) {
    ids.push_back(ranked[r].id);
    scene.clusters.push_back({r + 1, ranked[r].mass, 0, cluster_colour(r + 1)});
  }
  const std::size_t n = pos.size() / 3;
  std::size_t selected = 0;
  for (std::size_t p = 0; p < n; ++p) selected += in_view(opt, L, pos[3 * p + 2]);
  // The 3d view keeps every stride-th selected particle, so the picture is deterministic.
  const std::size_t stride = opt.view == SnapshotView::k3d ? (selected + opt.max_points - 1) / opt.max_points : 1;
  std::vector<SnapshotPoint> coloured;
  std::size_t seen = 0;
  for (std::size_t p = 0; p < n; ++p) {
    const double x = pos[3 * p], y = pos[3 * p + 1], z = pos[3 * p + 2];
    if (!in_view(opt, L, z) || seen++ % std::max<std::size_t>(stride, 1) != 0) continue;
    const std::int32_t id = lab.cluster_of(grid.cell_of(x, y, z));
    const auto it = std::find(ids.begin(), ids.end(), id);
    if (it == ids.end()) {
      scene.points.push_back({x, y, z, kOtherClusters});
    } else {
      auto& c = scene.clusters[it - ids.begin()];
      ++c.shown;
      coloured.push_back({x, y, z, c.rgb});
    }
  }
  scene.points.insert(scene.points.end(), coloured.begin(), coloured.end());
  return scene;
}

}  // namespace coolgas
