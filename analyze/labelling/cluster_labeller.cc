#include "analyze/labelling/cluster_labeller.h"

#include <algorithm>
#include <bit>
#include <limits>
#include <numeric>
#include <string>

#include "analyze/labelling/cluster_contacts.h"
#include "common/error.h"

namespace coolgas {

// Numbers the runs of plane k, gives each its number of particles and links
// it to the runs of the planes before: all while the plane is in cache.
void ClusterLabeller::add_plane(int k) {
  const std::int32_t first = runs_.size();
  runs_.add_plane(occ_, k);
  mass_.resize(static_cast<std::size_t>(runs_.size()), 0);
  parent_.resize(mass_.size());
  std::iota(parent_.begin() + first, parent_.end(), first);
  for (std::uint32_t b : occ_.plane_particles(k)) ++mass_[runs_.run_at_bit(b)];
  walk_plane_contacts(occ_, runs_, k, [&](std::int32_t a, std::int32_t b) { unite(a, b); });
}

// Rem's union with splicing: climb both paths at once, always from the
// higher parent, re-pointing each visited node to the other path's lower
// parent, until the two meet or one reaches a root, which is then linked.
void ClusterLabeller::unite(std::int32_t x, std::int32_t y) {
  std::int32_t* p = parent_.data();
  while (p[x] != p[y]) {
    if (p[x] > p[y]) {
      if (x == p[x]) {
        p[x] = p[y];
        return;
      }
      const std::int32_t z = p[x];
      p[x] = p[y];
      x = z;
    } else {
      if (y == p[y]) {
        p[y] = p[x];
        return;
      }
      const std::int32_t z = p[y];
      p[y] = p[x];
      y = z;
    }
  }
}

// parent[r] <= r, so in increasing order each parent is final before it is
// used. Written without branches: whether a run is a root is unpredictable.
void ClusterLabeller::flatten() {
  const auto nruns = static_cast<std::int32_t>(parent_.size());
  roots_.resize(parent_.size());
  std::size_t nroots = 0;
  for (std::int32_t r = 0; r < nruns; ++r) {
    const std::int32_t root = parent_[parent_[r]];
    const bool is_root = root == r;
    parent_[r] = root;
    roots_[nroots] = r;
    nroots += is_root;
    mass_[root] += is_root ? 0 : mass_[r];
  }
  roots_.resize(nroots);
}

void ClusterLabeller::label(const ClusterGrid& grid, std::span<const double> positions) {
  const std::size_t n = positions.size() / 3;
  if (n > std::size_t(std::numeric_limits<std::int32_t>::max()))
    throw InputError("too many particles for the cluster labeller: " + std::to_string(n) + " (at most 2^31 - 1)");
  mass_.clear();
  parent_.clear();
  runs_.reset(grid);
  occ_.build(grid, positions, [&](int k) { add_plane(k); });
  flatten();
}

std::int32_t ClusterLabeller::cluster_of(std::int64_t c) const {
  const std::int64_t n = occ_.grid().per_side();
  const std::int64_t x = c % n, r = c / n;
  return occ_.occupied(x, r) ? parent_[runs_.run_at(r, int(x))] : -1;
}

std::vector<Cluster> ClusterLabeller::ranked() const {
  // Roots are the lowest runs of their clusters: walking the run starts in
  // raster order meets each root at the cluster's smallest cell.
  std::vector<Cluster> out;
  out.reserve(roots_.size());
  const std::int64_t n = occ_.grid().per_side();
  const int words = occ_.words_per_row();
  std::size_t next = 0;
  for (std::int64_t r = 0; r < occ_.rows() && next < roots_.size(); ++r) {
    for (int w = 0; w < words; ++w) {
      for (std::uint64_t s = runs_.starts(r * words + w); s; s &= s - 1) {
        const int x = 64 * w + std::countr_zero(s);
        if (next < roots_.size() && runs_.run_at(r, x) == roots_[next]) {
          out.push_back({mass_[roots_[next]], x + n * r, roots_[next]});
          ++next;
        }
      }
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const Cluster& a, const Cluster& b) { return a.mass > b.mass; });
  return out;
}

}  // namespace coolgas
