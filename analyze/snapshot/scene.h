// What coolgas-snapshot draws: the particles of one frame, coloured by
// cluster like the paper's Fig. 3 (upper panels): the largest clusters in
// distinct colours, all others grey. For ballistic aggregation the clusters
// are the aggregates themselves, drawn at their true diameter m^(1/3)
// (volumes add, unit spheres; in the plane of disks m^(1/2), areas add) and
// ranked by mass.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "analyze/labelling/cluster_labeller.h"

namespace coolgas {

enum class SnapshotView {
  kSlab,  // particles with |z - L/2| < thickness/2, seen along z
  k3d,    // all particles in perspective (subsampled to max_points)
  kPlane  // a 2D file: every disk in the square, at true size
};

struct SnapshotOptions {
  SnapshotView view = SnapshotView::kSlab;
  double thickness = 4;              // slab thickness [sigma]
  int colored = 8;                   // largest clusters drawn in colour (<= palette size)
  std::int64_t max_points = 300000;  // 3d view: at most this many particles drawn
};

struct SnapshotPoint {
  double x, y, z;
  std::uint32_t rgb;      // 0xRRGGBB
  double diameter = 1;    // [sigma]
};

// A coloured cluster, for the legend.
struct ShownCluster {
  int rank = 0;            // 1 = largest
  std::int64_t mass = 0;   // particles in the whole cluster
  std::int64_t shown = 0;  // particles of it in the picture
  std::uint32_t rgb = 0;
};

struct SnapshotScene {
  std::vector<SnapshotPoint> points;  // grey ones first, so colours are drawn on top
  std::vector<ShownCluster> clusters;
};

// Colour of the rank-th largest cluster (rank >= 1), and of the others.
std::uint32_t cluster_colour(int rank);
inline constexpr std::uint32_t kOtherClusters = 0xbbbbbb;
int palette_size();

// Labels the clusters of the frame and picks and colours the particles to draw.
SnapshotScene make_scene(const ClusterGrid& grid, std::span<const double> positions, const SnapshotOptions& opt);

// The aggregates of a ballistic-aggregation frame (mass in particles, id the
// stable aggregate id): ranked by mass, ties by smaller id; box side L.
SnapshotScene make_aggregate_scene(double L, std::span<const double> positions, std::span<const double> mass,
                                   std::span<const std::int32_t> id, const SnapshotOptions& opt);

}  // namespace coolgas
