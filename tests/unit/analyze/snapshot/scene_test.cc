// What coolgas-snapshot draws: the slab holds exactly the particles with
// |z - L/2| < thickness/2, the largest clusters get the palette colours in
// rank order, the rest grey, and grey comes first so colours are on top.
#include "analyze/snapshot/scene.h"

#include <gtest/gtest.h>

#include "common/error.h"

namespace coolgas {
namespace {

// L = 10: a line of 5 cells along x (mass 5), a pair (mass 2) and a
// singleton in the plane z = 5.5, and one particle at z = 0.5.
std::vector<double> positions() {
  std::vector<double> p;
  for (int i = 0; i < 5; ++i) p.insert(p.end(), {i + 0.5, 1.5, 5.5});
  p.insert(p.end(), {1.5, 6.5, 5.5, 2.5, 6.5, 5.5});
  p.insert(p.end(), {7.5, 7.5, 5.5});
  p.insert(p.end(), {7.5, 7.5, 0.5});
  return p;
}

TEST(SnapshotScene, SlabColoursTheLargestClustersInRankOrder) {
  SnapshotOptions o;
  o.thickness = 2;  // 4 < z < 6
  o.colored = 2;
  const auto s = make_scene(ClusterGrid(10.0, Geometry(3)), positions(), o);
  ASSERT_EQ(s.points.size(), 8u);  // the particle at z = 0.5 is outside the slab
  ASSERT_EQ(s.clusters.size(), 2u);
  EXPECT_EQ(s.clusters[0].mass, 5);
  EXPECT_EQ(s.clusters[0].shown, 5);
  EXPECT_EQ(s.clusters[0].rgb, cluster_colour(1));
  EXPECT_EQ(s.clusters[1].mass, 2);
  EXPECT_EQ(s.clusters[1].rgb, cluster_colour(2));
  EXPECT_NE(cluster_colour(1), cluster_colour(2));
  EXPECT_EQ(s.points[0].rgb, kOtherClusters);  // the singleton, first
  EXPECT_EQ(s.points[0].x, 7.5);
  int blue = 0;
  for (const auto& p : s.points) blue += p.rgb == cluster_colour(1);
  EXPECT_EQ(blue, 5);
}

TEST(SnapshotScene, ThreeDimensionalViewKeepsAtMostMaxPoints) {
  SnapshotOptions o;
  o.view = SnapshotView::k3d;
  o.colored = 0;
  o.max_points = 3;
  const auto s = make_scene(ClusterGrid(10.0, Geometry(3)), positions(), o);
  EXPECT_EQ(s.points.size(), 3u);  // every 3rd of the 9 particles
  EXPECT_TRUE(s.clusters.empty());
  o.max_points = 100;
  EXPECT_EQ(make_scene(ClusterGrid(10.0, Geometry(3)), positions(), o).points.size(), 9u);
}

// Aggregates: ranked by mass (ties by the smaller id), drawn at diameter
// m^(1/3), and in the slab when they reach into it: |z - L/2| < (t + d - 1)/2.
TEST(SnapshotScene, AggregatesAreRankedByMassAndDrawnAtTheirDiameter) {
  const std::vector<double> pos{2, 2, 5, 6, 6, 5, 8, 2, 8.2, 2, 8, 9.5};
  const std::vector<double> mass{8, 27, 8, 1};
  const std::vector<std::int32_t> id{4, 7, 2, 9};
  SnapshotOptions o;
  o.thickness = 2;  // unit spheres: 4 < z < 6
  o.colored = 3;
  const auto s = make_aggregate_scene(10, pos, mass, id, o);
  ASSERT_EQ(s.clusters.size(), 3u);
  EXPECT_EQ(s.clusters[0].mass, 27);
  EXPECT_EQ(s.clusters[1].mass, 8);  // id 2 before id 4
  EXPECT_EQ(s.clusters[2].mass, 8);
  // in view: m = 27 (d = 3) at z = 5; m = 8 (d = 2) at z = 5; m = 8 at z = 8.2 (2.7 from the middle, above 1.5)
  // is not; the unit sphere at z = 9.5 is not.
  ASSERT_EQ(s.points.size(), 2u);
  EXPECT_EQ(s.points[0].rgb, cluster_colour(3));  // id 4 at (2, 2): rank 3
  EXPECT_DOUBLE_EQ(s.points[0].diameter, 2);
  EXPECT_EQ(s.points[1].rgb, cluster_colour(1));
  EXPECT_DOUBLE_EQ(s.points[1].diameter, 3);
  EXPECT_EQ(s.clusters[1].shown, 0);  // id 2 lies outside the slab
}

TEST(SnapshotScene, RejectsBadOptions) {
  SnapshotOptions o;
  o.colored = palette_size() + 1;
  EXPECT_THROW(make_scene(ClusterGrid(10.0, Geometry(3)), positions(), o), InputError);
  o.colored = 1;
  o.thickness = 0;
  EXPECT_THROW(make_scene(ClusterGrid(10.0, Geometry(3)), positions(), o), InputError);
}

}  // namespace
}  // namespace coolgas
