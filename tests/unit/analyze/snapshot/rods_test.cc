// What coolgas-snapshot draws of a 1D file (rods on a ring): a space-time
// diagram, one row per dump up to --time, each rod at its true length (an
// aggregate of mass m: m) coloured by v / v_rms of its dump (mass-weighted
// for aggregates); the options of the 2D and 3D pictures are refused with
// one line; the table has one row per dump.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "analyze/snapshot/space_time.h"
#include "analyze/snapshot/tool.h"
#include "common/error.h"
#include "common/trajectory/h5md_writer.h"
#include "common/tsv.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

TEST(RodSnapshot, ARowScalesVelocitiesByItsDumpsRms) {
  // v = 3, -1, -1, 1 (y and z as the frame reader gives them, 0): <v^2> = 3, v_rms = sqrt 3.
  const std::vector<double> pos{0.5, 0, 0, 2.5, 0, 0, 4.0, 0, 0, 7.0, 0, 0};
  const std::vector<double> vel{3, 0, 0, -1, 0, 0, -1, 0, 0, 1, 0, 0};
  const SpaceTimeRow r = space_time_row(2.0, pos, vel, {});
  EXPECT_EQ(r.t, 2.0);
  EXPECT_DOUBLE_EQ(r.v_rms, std::sqrt(3.0));
  ASSERT_EQ(r.rods.size(), 4u);
  EXPECT_DOUBLE_EQ(r.rods[0].v, std::sqrt(3.0));
  EXPECT_DOUBLE_EQ(r.rods[1].v, -1 / std::sqrt(3.0));
  EXPECT_EQ(r.rods[3].x, 7.0);
  for (const auto& rod : r.rods) EXPECT_EQ(rod.length, 1.0);
  // Aggregates of masses 1 and 3: lengths add, v_rms = sqrt((1*9 + 3*1)/4) = sqrt 3.
  const SpaceTimeRow a = space_time_row(2.0, {pos.data(), 6}, {vel.data(), 6}, std::vector<double>{1, 3});
  EXPECT_DOUBLE_EQ(a.v_rms, std::sqrt(3.0));
  EXPECT_EQ(a.rods[1].length, 3.0);
  // A row at rest is grey, not NaN.
  EXPECT_EQ(space_time_row(0, pos, std::vector<double>(12, 0.0), {}).rods[0].v, 0.0);
}

// Rows as vectors of their rods' lengths, coloured on the fixed scale; at
// most about ten rows labelled, the first with its time.
TEST(RodSnapshot, TheScriptDrawsRowsOfSegmentsOnAFixedColourScale) {
  std::vector<SpaceTimeRow> rows(25);
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i].t = i == 0 ? 0.0 : std::pow(10.0, 0.25 * double(i));
  const PlotOptions o{.title = "rods", .L = 100};
  const std::string s = space_time_script(rows, o, "d.dat", "p.png");
  EXPECT_NE(s.find("set xrange [0:100]"), std::string::npos) << s;
  EXPECT_NE(s.find("set yrange [-0.5:24.5]"), std::string::npos) << s;
  EXPECT_NE(s.find("set ytics ('0' 0, '5.62' 3, '31.6' 6, "), std::string::npos) << s;
  EXPECT_NE(s.find("set cbrange [-2:2]"), std::string::npos) << s;
  EXPECT_NE(s.find("using 1:2:3:(0):4 with vectors nohead"), std::string::npos) << s;
}

std::string write_rod_run(const std::string& dir) {
  std::string path = dir + "/rods.h5";
  RunParameters p;
  p.N = 4;
  p.L = 12;
  H5mdWriter w = H5mdWriter::create(path, p, true, Geometry(1));
  const std::int32_t img[12] = {};
  for (int f = 0; f < 4; ++f) {
    const double pos[12] = {1, 0, 0, 4, 0, 0, 6.5, 0, 0, 11.5, 0, 0};
    const double s = std::pow(0.5, f);  // cooling: v_rms halves from dump to dump
    const double vel[12] = {s, 0, 0, -s, 0, 0, s, 0, 0, -s, 0, 0};
    w.add_frame({f == 0 ? 0.0 : std::pow(10.0, f - 1), f, 0, pos, img, vel});
  }
  return path;
}

TEST(RodSnapshot, TheToolDrawsTheDumpsUpToTheTimeAndListsThem) {
  const std::string dir = test::scratch_dir("snapshot_rods");
  SnapshotToolOptions o;
  o.input = write_rod_run(dir);
  o.times = {10};
  o.output = dir + "/rods.png";
  o.force = true;
  std::stringstream out;
  run_snapshot(o, out);
  const Table t = read_table(out, "out");
  EXPECT_EQ(t.get("dimension"), "1");
  EXPECT_EQ(t.get("view"), "space-time");
  EXPECT_EQ(t.columns, (std::vector<std::string>{"t", "particles", "v_rms"}));
  ASSERT_EQ(t.rows.size(), 3u);  // t = 0, 1, 10
  EXPECT_EQ(t.rows[2][0], 10.0);
  for (std::size_t r = 0; r < 3; ++r) {
    EXPECT_EQ(t.rows[r][1], 4.0);
    EXPECT_DOUBLE_EQ(t.rows[r][2], std::pow(0.5, double(r)));
  }
  std::ifstream png(o.output, std::ios::binary);
  char magic[4] = {};
  png.read(magic, 4);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
}

TEST(RodSnapshot, TheOptionsOfThePlaneAndSlabPicturesAreRefused) {
  const std::string dir = test::scratch_dir("snapshot_rods_refused");
  SnapshotToolOptions o;
  o.input = write_rod_run(dir);
  o.times = {1};
  o.output = dir + "/rods.png";
  for (auto [only_3d, not_1d] : {std::pair{"--view 3d", ""}, {"", "--colored 3"}, {"", "--max-points 10"}}) {
    o.only_3d = only_3d;
    o.not_1d = not_1d;
    std::stringstream out;
    try {
      run_snapshot(o, out);
      FAIL() << only_3d << not_1d << " was accepted";
    } catch (const InputError& e) {
      const std::string given = std::string(only_3d) + not_1d;
      EXPECT_NE(std::string(e.what()).find(given + " is not for 1D trajectories (rods)"), std::string::npos) << e.what();
    }
  }
  EXPECT_FALSE(std::filesystem::exists(o.output));
}

}  // namespace
}  // namespace coolgas
