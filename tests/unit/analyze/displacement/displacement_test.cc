// coolgas-displacement end to end on files from the real writer, in
// d = 1, 2, 3: particles in free flight, wrapped into the box with their
// image counts as the engine keeps them, crossing the box many times
// between dumps. Free flight is ballistic exactly: msd = <|v|^2> dt^2 to
// round-off, the velocities keep their correlation 1, and nothing depends
// on how far apart the dumps are.
#include "analyze/displacement/tool.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "analyze/displacement/displacement_table.h"
#include "common/error.h"
#include "common/random.h"
#include "common/trajectory/h5md_writer.h"
#include "common/tsv.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

constexpr double kL = 10;
const double kTimes[] = {0, 0.5, 3, 40};

struct FreeFlight {
  std::vector<double> x0, v;  // unwrapped start and velocity, 3 per particle (past d: 0)
  double mean_v2 = 0;
};

FreeFlight free_flight(std::size_t n, Geometry g, std::uint64_t seed) {
  Random rng(seed);
  FreeFlight f{std::vector<double>(3 * n, 0.0), std::vector<double>(3 * n, 0.0)};
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < g.d(); ++k) {
      f.x0[3 * i + k] = kL * (4 * rng.uniform() - 2);  // some start in other images
      f.v[3 * i + k] = rng.normal();
      f.mean_v2 += f.v[3 * i + k] * f.v[3 * i + k] / double(n);
    }
  return f;
}

// Writes the dumps at kTimes: positions wrapped into [0, L), images counting the wraps.
std::string write_run(const std::string& name, const FreeFlight& f, Geometry g) {
  std::string path = test::scratch_dir(name) + "/run.h5";
  const std::size_t n = f.x0.size() / 3;
  RunParameters p;
  p.N = std::int64_t(n);
  p.L = kL;
  H5mdWriter w = H5mdWriter::create(path, p, false, g);
  std::vector<double> pos(3 * n);
  std::vector<std::int32_t> img(3 * n);
  for (double t : kTimes) {
    for (std::size_t k = 0; k < 3 * n; ++k) {
      const double x = f.x0[k] + f.v[k] * t;
      img[k] = std::int32_t(std::floor(x / kL));
      pos[k] = x - kL * img[k];
    }
    w.add_frame({t, std::int64_t(t * 100), 0, pos.data(), img.data(), f.v.data()});
  }
  return path;
}

Table run(const DisplacementOptions& o) {
  std::stringstream out;
  run_displacement(o, out);
  return read_table(out, o.input);
}

class EveryDimension : public ::testing::TestWithParam<int> {};

TEST_P(EveryDimension, FreeFlightIsBallisticExactly) {
  const Geometry g(GetParam());
  const FreeFlight f = free_flight(400, g, 11 + GetParam());
  DisplacementOptions o;
  o.input = write_run("displacement_" + std::to_string(g.d()) + "d", f, g);
  const Table table = run(o);
  ASSERT_EQ(table.columns, displacement_columns());
  ASSERT_EQ(table.rows.size(), 4u);
  for (const auto& row : table.rows) {
    const double dt = row[table.column("dt")];
    EXPECT_NEAR(row[table.column("msd")], f.mean_v2 * dt * dt, 1e-12 * (1 + f.mean_v2 * dt * dt)) << "dt = " << dt;
    EXPECT_NEAR(row[table.column("vacf_norm")], 1, 1e-14);
    EXPECT_NEAR(row[table.column("T")], f.mean_v2 / g.d(), 1e-14);
    if (dt > 0) EXPECT_NEAR(row[table.column("D_apparent")], f.mean_v2 * dt / (2 * g.d()), 1e-11 * dt);
  }
  // From another reference: displacements over 40 - 3.
  o.from = 3;
  o.times = {40};
  const Table later = run(o);
  ASSERT_EQ(later.rows.size(), 1u);
  EXPECT_EQ(later.rows[0][later.column("dt")], 37);
  EXPECT_NEAR(later.rows[0][later.column("msd")], f.mean_v2 * 37 * 37, 1e-12 * f.mean_v2 * 37 * 37);
  EXPECT_NE(later.get("reference")->find("t_ref = 3 (--from)"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(D, EveryDimension, ::testing::Values(1, 2, 3));

// The row checks what it compares: the same particles, the same box.
TEST(Displacement, RowRefusesOtherParticlesOrAnotherBox) {
  const std::vector<double> p{1, 2, 3, 4, 5, 6}, v{1, 0, 0, 0, 1, 0};
  const std::vector<std::int32_t> img(6, 0);
  const DisplacementOrigin origin(kL, p, img, v, Geometry(3));
  EXPECT_THROW(displacement_row(origin, 0, kL, 1, kL, std::span(p).first(3), std::span(img).first(3), std::span(v).first(3)),
               InputError);
  EXPECT_THROW(displacement_row(origin, 0, kL, 1, 2 * kL, p, img, v), InputError);
  EXPECT_EQ(displacement_row(origin, 0, kL, 1, kL, p, img, v).rows[0][2], 0.0);  // msd of particles that stayed
}

}  // namespace
}  // namespace coolgas
