// What coolgas-snapshot draws of a 2D file (the plane view): every disk of
// the square, at its true size, coloured by its cluster of unit squares
// (edge neighbours, periodic); ballistic aggregates of disks have the
// diameter m^(1/2) (areas add).
#include <gtest/gtest.h>

#include <cmath>

#include "analyze/snapshot/scene.h"

namespace coolgas {
namespace {

// L = 10: a row of 4 squares that wraps across x = 0 (mass 4), a pair along
// y (mass 2), and two disks in squares that meet only at a corner.
std::vector<double> disks() {
  std::vector<double> p;
  for (double x : {8.5, 9.5, 0.5, 1.5}) p.insert(p.end(), {x, 3.5, 0.0});
  p.insert(p.end(), {5.5, 6.5, 0.0, 5.5, 7.5, 0.0});
  p.insert(p.end(), {2.5, 8.5, 0.0, 3.5, 9.5, 0.0});
  return p;
}

TEST(DiskSnapshot, ThePlaneShowsEveryDiskColouredByItsCluster) {
  SnapshotOptions o;
  o.view = SnapshotView::kPlane;
  o.colored = 3;
  const auto s = make_scene(ClusterGrid(10.0, Geometry(2)), disks(), o);
  ASSERT_EQ(s.points.size(), 8u);
  ASSERT_EQ(s.clusters.size(), 3u);
  EXPECT_EQ(s.clusters[0].mass, 4);
  EXPECT_EQ(s.clusters[0].shown, 4);
  EXPECT_EQ(s.clusters[1].mass, 2);
  EXPECT_EQ(s.clusters[2].mass, 1);  // the corner pair is two clusters of one
  int grey = 0, first = 0;
  for (const auto& p : s.points) {
    grey += p.rgb == kOtherClusters;
    first += p.rgb == cluster_colour(1);
    EXPECT_EQ(p.diameter, 1.0);
  }
  EXPECT_EQ(grey, 1);
  EXPECT_EQ(first, 4);
  EXPECT_EQ(s.points[0].rgb, kOtherClusters);  // grey first, colours on top
}

TEST(DiskSnapshot, AggregatesOfDisksAddTheirAreas) {
  SnapshotOptions o;
  o.view = SnapshotView::kPlane;
  o.colored = 1;
  const std::vector<double> pos{1, 1, 0, 5, 5, 0};
  const std::vector<double> mass{4, 9};
  const std::vector<std::int32_t> id{0, 1};
  const auto s = make_aggregate_scene(10.0, pos, mass, id, o);
  ASSERT_EQ(s.points.size(), 2u);
  EXPECT_EQ(s.points[0].diameter, 2.0);  // grey, m = 4
  EXPECT_EQ(s.points[1].diameter, 3.0);  // the largest, m = 9
}

}  // namespace
}  // namespace coolgas
