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

// A sphere of diameter d is in the slab when it reaches into it by more than
// a unit sphere's half: for unit spheres, |z - L/2| < thickness/2.
bool in_view(const SnapshotOptions& o, double L, double z, double d) {
  return o.view != SnapshotView::kSlab || std::abs(z - 0.5 * L) < 0.5 * (o.thickness + d - 1);
}

}  // namespace

int palette_size() { return static_cast<int>(kPalette.size()); }

std::uint32_t cluster_colour(int rank) {
  return rank >= 1 && rank <= palette_size() ? kPalette[rank - 1] : kOtherClusters;
}

namespace {

// Picks the particles in view (every stride-th in the 3d view, so the picture
// is deterministic) and colours them: rank_of(p) is the rank of p's cluster
// among scene.clusters (1-based), 0 for grey. Grey points come first, so the
// colours are drawn on top.
template <class RankOf, class DiameterOf>
void add_points(SnapshotScene& scene, double L, std::span<const double> pos, const SnapshotOptions& opt,
                RankOf rank_of, DiameterOf diameter_of) {
  const std::size_t n = pos.size() / 3;
  std::size_t selected = 0;
  for (std::size_t p = 0; p < n; ++p) selected += in_view(opt, L, pos[3 * p + 2], diameter_of(p));
  const std::size_t stride = opt.view == SnapshotView::k3d ? (selected + opt.max_points - 1) / opt.max_points : 1;
  std::vector<SnapshotPoint> coloured;
  std::size_t seen = 0;
  for (std::size_t p = 0; p < n; ++p) {
    const double x = pos[3 * p], y = pos[3 * p + 1], z = pos[3 * p + 2];
    const double d = diameter_of(p);
    if (!in_view(opt, L, z, d) || seen++ % std::max<std::size_t>(stride, 1) != 0) continue;
    const int rank = rank_of(p);
    if (rank == 0) {
      scene.points.push_back({x, y, z, kOtherClusters, d});
    } else {
      auto& c = scene.clusters[rank - 1];
      ++c.shown;
      coloured.push_back({x, y, z, c.rgb, d});
    }
  }
  scene.points.insert(scene.points.end(), coloured.begin(), coloured.end());
}

}  // namespace

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
  const auto rank_of = [&](std::size_t p) {
    const std::int32_t id = lab.cluster_of(grid.cell_of(pos[3 * p], pos[3 * p + 1], pos[3 * p + 2]));
    const auto it = std::find(ids.begin(), ids.end(), id);
    return it == ids.end() ? 0 : int(it - ids.begin()) + 1;
  };
  add_points(scene, L, pos, opt, rank_of, [](std::size_t) { return 1.0; });
  return scene;
}

SnapshotScene make_aggregate_scene(double L, std::span<const double> pos, std::span<const double> mass,
                                   std::span<const std::int32_t> id, const SnapshotOptions& opt) {
  check(opt, L);
  std::vector<std::size_t> order(mass.size());
  for (std::size_t p = 0; p < order.size(); ++p) order[p] = p;
  const std::size_t shown = std::min<std::size_t>(std::size_t(opt.colored), order.size());
  std::partial_sort(order.begin(), order.begin() + std::ptrdiff_t(shown), order.end(), [&](std::size_t a, std::size_t b) {
    return mass[a] != mass[b] ? mass[a] > mass[b] : id[a] < id[b];
  });
  SnapshotScene scene;
  std::vector<int> rank(mass.size(), 0);
  for (std::size_t r = 0; r < shown; ++r) {
    rank[order[r]] = int(r) + 1;
    scene.clusters.push_back({int(r) + 1, std::llround(mass[order[r]]), 0, cluster_colour(int(r) + 1)});
  }
  const Geometry g(opt.view == SnapshotView::kPlane ? 2 : 3);  // the plane view is a 2D file's
  add_points(scene, L, pos, opt, [&](std::size_t p) { return rank[p]; },
             [&](std::size_t p) { return g.diameter_of_mass(mass[p]); });
  return scene;
}

}  // namespace coolgas
