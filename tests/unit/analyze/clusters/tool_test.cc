// coolgas-clusters end to end on files written by the real H5MD writer: the
// tables follow the shared shapes of data-schema/tsv-tables.md and their
// numbers obey the definitions there exactly.
#include "analyze/clusters/tool.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "analyze/clusters/mass_distribution.h"
#include "common/error.h"
#include "common/trajectory/h5md_writer.h"
#include "common/tsv.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

// A 6x6x6-cell box (L = 6.3) with 9 particles: a mass-4 cluster wrapping the
// x face (two centres share a cell), a mass-3 line along z, two singletons.
// The second frame moves everything into one cell: one cluster of mass 9.
std::string write_run(const std::string& name) {
  std::string path = test::scratch_dir(name) + "/run.h5";
  RunParameters p;
  p.N = 9;
  p.L = 6.3;
  p.seed = 3;
  p.phi = 9 * M_PI / 6 / std::pow(6.3, 3);
  H5mdWriter w = H5mdWriter::create(path, p, false, Geometry(3));
  const double f0[27] = {0.2, 1.2, 1.2, 0.6, 1.2, 1.2, 6.2, 1.2, 1.2, 5.4, 1.3, 1.1,  // wraps x
                         3.2, 3.2, 0.2, 3.2, 3.2, 1.2, 3.2, 3.2, 2.2,                 // line along z
                         3.2, 5.5, 5.5, 1.2, 3.2, 4.2};                               // singletons
  double f1[27];
  for (int i = 0; i < 27; ++i) f1[i] = 2.5 + 0.01 * i;
  const std::int32_t img[27] = {};
  const double vel[27] = {};
  w.add_frame({0.0, 0, 0, f0, img, vel});
  w.add_frame({10.0, 100, 0, f1, img, vel});
  return path;
}

// The tool's own output, read back with the TSV reader every tool uses.
Table run(const ClustersOptions& opt) {
  std::stringstream out;
  run_clusters(opt, out);
  return read_table(out, "out");
}

TEST(ClusterTool, SeriesFollowsTheSharedShape) {
  ClustersOptions opt;
  opt.input = write_run("clusters_series");
  opt.series = true;
  const Table t = run(opt);
  EXPECT_EQ(t.columns, (std::vector<std::string>{"t", "M0", "M1", "M2", "M_avg", "M_max", "largest_fraction"}));
  EXPECT_EQ(t.get("N"), "9");
  ASSERT_EQ(t.rows.size(), 2u);
  const double V = std::pow(6.3, 3);
  // Frame 0: masses {4, 3, 1, 1}.
  const auto& r = t.rows[0];
  EXPECT_DOUBLE_EQ(r[t.column("M0")], 4 / V);
  EXPECT_DOUBLE_EQ(r[t.column("M1")], 9 / V);
  EXPECT_DOUBLE_EQ(r[t.column("M2")], (16 + 9 + 1 + 1) / V);
  EXPECT_DOUBLE_EQ(r[t.column("M_avg")], 9.0 / 4);
  EXPECT_EQ(r[t.column("M_max")], 4);
  EXPECT_DOUBLE_EQ(r[t.column("largest_fraction")], 4.0 / 9);
  // Frame 1: one cluster holds everything.
  EXPECT_EQ(t.rows[1][t.column("t")], 10);
  EXPECT_EQ(t.rows[1][t.column("M_max")], 9);
  EXPECT_EQ(t.rows[1][t.column("largest_fraction")], 1);
}

TEST(ClusterTool, DistributionFollowsTheSharedShape) {
  ClustersOptions opt;
  opt.input = write_run("clusters_distribution");
  opt.times = {0.1};  // nearest dump: t = 0
  const Table t = run(opt);
  EXPECT_EQ(t.columns, (std::vector<std::string>{"t", "m", "dm", "N", "x", "y"}));
  const double V = std::pow(6.3, 3), m_avg = 9.0 / 4;
  // Masses 1, 3 and 4 fall in three different bins (1, 3 and [4, 5] with 10 per decade).
  ASSERT_EQ(t.rows.size(), 3u);
  const LogBins bins(10, 9);
  const std::vector<std::int64_t> mass = {1, 3, 4};
  const std::vector<double> count = {2, 1, 1};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& r = t.rows[i];
    const int k = bins.index(mass[i]);
    const double dm = double(bins.width(k));
    EXPECT_EQ(r[t.column("m")], bins.center(k));
    EXPECT_EQ(r[t.column("dm")], dm);
    EXPECT_DOUBLE_EQ(r[t.column("N")], count[i] / (V * dm));
    EXPECT_DOUBLE_EQ(r[t.column("x")], bins.center(k) / m_avg);
    EXPECT_DOUBLE_EQ(r[t.column("y")], count[i] / (V * dm) * m_avg * m_avg);
  }
  EXPECT_EQ(bins.width(bins.index(4)), 2);
}

TEST(ClusterTool, ScaledIsTheDistributionsXAndY) {
  // --scaled writes the paper's Fig. 3 variables alone: the same x = m/M_avg
  // and y = N M_avg^2 as the full table, row for row.
  ClustersOptions opt;
  opt.input = write_run("clusters_scaled");
  const Table full = run(opt);
  opt.scaled = true;
  const Table scaled = run(opt);
  EXPECT_EQ(scaled.columns, (std::vector<std::string>{"t", "x", "y"}));
  EXPECT_EQ(scaled.column_values("x"), full.column_values("x"));
  EXPECT_EQ(scaled.column_values("y"), full.column_values("y"));
  EXPECT_EQ(scaled.row_block, full.row_block);
}

TEST(MassHistogram, BinsConserveClustersAndMass) {
  MassHistogram h(5, 100000);
  std::int64_t total = 0;
  for (std::int64_t m = 1; m <= 30000; m += 7) {
    h.add(m);
    total += m;
  }
  std::int64_t clusters = 0;
  for (int k = 0; k < h.bins().size(); ++k) clusters += h.count(k);
  EXPECT_EQ(clusters, h.moments().clusters);
  EXPECT_EQ(h.moments().mass, total);
  EXPECT_EQ(h.moments().largest, 29996);
  EXPECT_EQ(h.count(h.bins().index(29996)) > 0, true);
  h.clear();
  EXPECT_EQ(h.moments().clusters, 0);
}

// A 1D file (rods on a ring of L = 10.5: 10 segments of 1.05): the rods
// 0.2, 0.7, 1.5 and 10.4 make one cluster of 4 across the ends, 5.5 and 6.0
// one of 2, 3.5 one of 1; densities are per unit length, M1 = N/L.
TEST(ClusterTool, A1DFileHasSegmentsAndDensitiesPerLength) {
  const std::string path = test::scratch_dir("clusters_rods") + "/run.h5";
  {
    RunParameters p;
    p.N = 7;
    p.L = 10.5;
    H5mdWriter w = H5mdWriter::create(path, p, false, Geometry(1));
    const double x[21] = {0.2, 0, 0, 0.7, 0, 0, 1.5, 0, 0, 10.4, 0, 0, 5.5, 0, 0, 6.0, 0, 0, 3.5, 0, 0};
    const std::int32_t img[21] = {};
    const double vel[21] = {};
    w.add_frame({0.0, 0, 0, x, img, vel});
  }
  ClustersOptions opt;
  opt.input = path;
  opt.series = true;
  const Table t = run(opt);
  EXPECT_EQ(t.get("dimension"), "1");
  EXPECT_EQ(t.get("cells"), "floor(L) segments of length L/floor(L); left and right neighbours; periodic");
  ASSERT_EQ(t.rows.size(), 1u);
  const auto& r = t.rows[0];
  EXPECT_DOUBLE_EQ(r[t.column("M0")], 3 / 10.5);
  EXPECT_DOUBLE_EQ(r[t.column("M1")], 7 / 10.5);
  EXPECT_DOUBLE_EQ(r[t.column("M2")], (16 + 4 + 1) / 10.5);
  EXPECT_EQ(r[t.column("M_max")], 4);
}

TEST(ClusterTool, RejectsFilesThatAreNotTrajectories) {
  const std::string dir = test::scratch_dir("clusters_bad");
  ClustersOptions opt;
  opt.input = dir + "/absent.h5";
  EXPECT_THROW(run(opt), InputError);
  opt.input = write_run("clusters_bad_bins");
  opt.bins_per_decade = 0;
  EXPECT_THROW(run(opt), InputError);
}

}  // namespace
}  // namespace coolgas
