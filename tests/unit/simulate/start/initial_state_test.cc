// Random initial positions (random sequential addition, with the voxel phase
// of Zhang & Torquato 2013 near saturation): exact count, no overlap, inside
// the box, deterministic per seed, uniform over the space left (the voxels'
// draws, and the saturation coverage), and a clear error beyond saturation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/error.h"
#include "simulate/start/initial_state.h"
#include "common/random.h"
#include "simulate/start/rsa_centre_grid.h"
#include "simulate/start/rsa_free_voxels.h"
#include "simulate/start/rsa_voxels.h"
#include "tests/support/min_distance.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

Scene positions_only(std::int64_t N, double phi, std::int64_t seed) {
  Scene s = test::elastic_scene(N, phi, seed);
  s.equilibrate = 0;  // the placement itself, not the melted fluid
  return s;
}

void expect_valid_packing(double phi) {
  const Scene s = positions_only(20000, phi, 5);
  const Particles p = initial_state(s);
  ASSERT_EQ(p.size(), std::size_t(s.N));
  for (const Vec3& r : p.r)
    for (int d = 0; d < 3; ++d) {
      ASSERT_GE(r[d], 0.0);
      ASSERT_LT(r[d], p.L);
    }
  EXPECT_GE(test::min_pair_distance(p), 1.0 - 1e-12);
}

TEST(RandomPlacement, NoOverlapAtPhi035) { expect_valid_packing(0.35); }
TEST(RandomPlacement, NoOverlapAtPhi036) { expect_valid_packing(0.36); }

TEST(RandomPlacement, SameSeedSamePositions) {
  const Particles a = initial_state(positions_only(20000, 0.35, 7));
  const Particles b = initial_state(positions_only(20000, 0.35, 7));
  const Particles c = initial_state(positions_only(20000, 0.35, 8));
  ASSERT_EQ(a.size(), b.size());
  bool same = true, differs = false;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int d = 0; d < 3; ++d) {
      same = same && a.r[i][d] == b.r[i][d];
      differs = differs || a.r[i][d] != c.r[i][d];
    }
  EXPECT_TRUE(same);
  EXPECT_TRUE(differs);
}

// The set-up's progress report (placement and equilibration, for the
// progress line) changes nothing: the same state bit for bit, and the
// placement's counts only grow, up to N, through both of its phases.
TEST(RandomPlacement, TheProgressReportChangesNothing) {
  Scene scene = positions_only(20000, 0.35, 7);
  scene.equilibrate = 0.2;
  std::vector<std::string> lines;
  const Particles quiet = initial_state(scene);
  const Particles told = initial_state(scene, nullptr, [&](const std::string& line, bool) { lines.push_back(line); });
  ASSERT_EQ(quiet.size(), told.size());
  bool same = true;
  for (std::size_t i = 0; i < quiet.size(); ++i)
    for (int d = 0; d < 3; ++d) same = same && quiet.r[i][d] == told.r[i][d] && quiet.v[i][d] == told.v[i][d];
  EXPECT_TRUE(same);
  long last = -1, updates = 0;
  bool equilibrated = false;
  for (const std::string& line : lines) {
    long n = 0;
    if (std::sscanf(line.c_str(), "placing at random: %ld of 20000", &n) == 1) {
      EXPECT_GE(n, last) << line;
      EXPECT_LE(n, 20000) << line;
      last = n, ++updates;
    }
    equilibrated = equilibrated || line.find("(100 %)") != std::string::npos;
  }
  EXPECT_GE(updates, 2);  // at least one per 4096 trials: 20000 spheres take more than 20000 trials
  EXPECT_TRUE(equilibrated);
}

// The saturation coverage of random sequential addition of equal spheres in
// 3D is phi_s = 0.384130 +- 0.000015 (Zhang & Torquato, PRE 88, 053312,
// 2013). It depends on each new centre being uniform over the space left:
// a sampler that drew cells uniformly instead of by the volume of their
// voxels gives 0.3872 here. Mean over 40 periodic boxes of side 15 (~2500
// spheres each) run to saturation: over 400 seeds one box gives 0.38415 with
// a spread (sd) of 0.00186, so the mean of 40 has sd 0.0003; boxes of side
// 10, 20 and 30 gave 0.38432, 0.38407 and 0.38416 (+- 0.0002), no visible
// finite-size shift. Tolerance 0.0012: four sd.
TEST(RandomPlacement, SaturationCoverageIsZhangAndTorquatos) {
  constexpr double L = 15;
  constexpr int kBoxes = 40;
  double placed = 0;
  for (int seed = 1; seed <= kBoxes; ++seed) {
    Random rng{std::uint64_t(seed)};
    placed += double(saturate_random_sequential(L, rng));
  }
  const double phi_s = placed / kBoxes * M_PI / (6 * L * L * L);
  EXPECT_NEAR(phi_s, 0.384130, 0.0012);
}

// Free points of a fixed packing, drawn through the voxels or by plain
// uniform trials, counted by sub-box of the box and by depth (distance to
// the nearest centre, less 1, in steps of 0.01).
class FreeSpace {
 public:
  static constexpr int kSide = 4, kDepths = 16;

  explicit FreeSpace(const Particles& p) : p_(p), grid_(p.L), voxels_(grid_.cells_per_side(), grid_.width()) {
    for (std::size_t i = 0; i < p.size(); ++i) grid_.insert(p.r[i], std::int32_t(i));
    voxels_.build([&](auto&& f) { grid_.for_each_centre(f); });
  }

  struct Counts {
    std::vector<double> by_box = std::vector<double>(kSide * kSide * kSide);
    std::vector<double> by_depth = std::vector<double>(kDepths);
  };

  // As in the voxel phase, without placing: a voxel by volume, a uniform
  // point in it; a failed trial refines the voxel.
  Counts through_voxels(int points, Random& rng) {
    Counts c;
    std::vector<Vec3> near, exact;
    for (int found = 0; found < points;) {
      const FreeVoxels::Voxel v = voxels_.draw(rng);
      const Vec3 corner = grid_.corner(v.cell);
      const Vec3 x = uniform_in(corner.x + v.lo.x, corner.y + v.lo.y, corner.z + v.lo.z, v.side, rng);
      if (count(x, c)) {
        ++found;
        continue;
      }
      near.clear();
      exact.clear();
      grid_.for_each_near(v.cell, [&](const Vec3& r, std::int32_t id) {
        near.push_back(r);
        exact.push_back(relative(p_.r[std::size_t(id)], corner));
      });
      if (!voxels_.refine(v, near)) voxels_.settle(v, exact);
    }
    return c;
  }

  Counts by_plain_trials(int points, Random& rng) {
    Counts c;
    for (int found = 0; found < points;) found += count(uniform_in(0, 0, 0, p_.L, rng), c);
    return c;
  }

 private:
  double image(double d) const { return d > p_.L / 2 ? d - p_.L : (d < -p_.L / 2 ? d + p_.L : d); }
  Vec3 relative(const Vec3& r, const Vec3& x) const { return {image(r.x - x.x), image(r.y - x.y), image(r.z - x.z)}; }
  Vec3 uniform_in(double x, double y, double z, double side, Random& rng) const {
    const double top = std::nextafter(p_.L, 0.0);
    return {std::min(x + side * rng.uniform(), top), std::min(y + side * rng.uniform(), top),
            std::min(z + side * rng.uniform(), top)};
  }
  // Counts x if it is free.
  bool count(const Vec3& x, Counts& c) const {
    double nearest2 = 4;  // (squared; the centres gathered are those within reach)
    grid_.for_each_near(std::size_t(grid_.cell_of(x)), [&](const Vec3&, std::int32_t id) {
      const Vec3 d = relative(p_.r[std::size_t(id)], x);
      nearest2 = std::min(nearest2, dot(d, d));
    });
    if (nearest2 < 1.0) return false;
    const auto sub = [&](double u) { return std::min(kSide - 1, int(u / p_.L * kSide)); };
    c.by_box[std::size_t((sub(x.z) * kSide + sub(x.y)) * kSide + sub(x.x))] += 1;
    c.by_depth[std::size_t(std::min(kDepths - 1, int((std::sqrt(nearest2) - 1) / 0.01)))] += 1;
    return true;
  }

  const Particles& p_;
  CentreGrid grid_;
  FreeVoxels voxels_;
};

// Two-sample chi-square of equal-sized samples.
double chi_square(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (a[k] + b[k] > 0) sum += (a[k] - b[k]) * (a[k] - b[k]) / (a[k] + b[k]);
  return sum;
}

// The voxel method must draw each new centre uniformly over the space left:
// that is what makes it RSA (Zhang & Torquato 2013). In a fixed packing
// (phi = 0.28, where one plain trial in ~170 is free), the free points it
// yields, refining its voxels as its trials fail, must be spread like those
// of plain uniform trials over the box: over 64 sub-boxes, and in depth,
// where any favour to the small voxels of refined regions shows at once
// (drawing a cell's voxels alike whatever their size gives a depth
// chi-square of ~2000; drawing cells uniformly ~2500, and ~740 by sub-box).
// 20000 points each; the limits are the 1e-4 tails of chi-square with 63 and
// 15 degrees of freedom (Wilson-Hilferty); ten seeds gave 47-78 and 8-28.
TEST(RandomPlacement, VoxelTrialsAreUniformOverTheSpaceLeft) {
  const Particles p = initial_state(positions_only(3000, 0.28, 11));
  FreeSpace space(p);
  Random rng{12};
  const FreeSpace::Counts voxels = space.through_voxels(20000, rng);
  const FreeSpace::Counts plain = space.by_plain_trials(20000, rng);
  EXPECT_LT(chi_square(voxels.by_box, plain.by_box), 113.7);
  EXPECT_LT(chi_square(voxels.by_depth, plain.by_depth), 44.6);
}

// The centres' grid answers "is a centre nearer than one diameter?" exactly
// as the all-centres test in double precision, whatever the width of its
// cells: one diameter (dense placements) or the mean spacing of a dilute
// gas (rsa_voxels.cc), where single-precision offsets are larger. 400
// centres in a box of side 24 (phi = 0.016, mean spacing 3.3); half of the
// 20000 query points lie at 1 +- 1e-9 .. 1e-3 from a centre, in every
// direction, so the band settled on exact positions is crossed often (and
// single precision alone gets some of them wrong).
TEST(CentreGrid, WideCellsGiveTheExactAnswersOfOneDiameterCells) {
  constexpr double L = 24;
  Random rng(11);
  std::vector<Vec3> r(400);
  for (Vec3& c : r) c = {L * rng.uniform(), L * rng.uniform(), L * rng.uniform()};
  CentreGrid fine(L), wide(L, 3.3);
  ASSERT_EQ(fine.cells_per_side(), 23);
  ASSERT_EQ(wide.cells_per_side(), 7);
  for (std::size_t i = 0; i < r.size(); ++i) fine.insert(r[i], std::int32_t(i)), wide.insert(r[i], std::int32_t(i));
  const auto image = [&](double d) { return d > L / 2 ? d - L : (d < -L / 2 ? d + L : d); };
  const auto near = [&](const Vec3& a, const Vec3& x) {
    const double dx = image(a.x - x.x), dy = image(a.y - x.y), dz = image(a.z - x.z);
    return dx * dx + dy * dy + dz * dz < 1.0;
  };
  int hits = 0, disagreements = 0;
  for (int q = 0; q < 20000; ++q) {
    Vec3 x{L * rng.uniform(), L * rng.uniform(), L * rng.uniform()};
    if (q % 2) {  // near the surface of a centre's exclusion sphere
      const Vec3& c = r[std::size_t(rng.below(r.size()))];
      const double u = 2 * rng.uniform() - 1, phi = 2 * M_PI * rng.uniform(), s = std::sqrt(1 - u * u);
      const double d = 1 + (rng.uniform() < 0.5 ? -1 : 1) * std::pow(10.0, -9 + 6 * rng.uniform());
      x = {c.x + d * s * std::cos(phi), c.y + d * s * std::sin(phi), c.z + d * u};
      for (int k = 0; k < 3; ++k) x[k] = x[k] < 0 ? x[k] + L : (x[k] >= L ? x[k] - L : x[k]);
    }
    const bool truth = std::any_of(r.begin(), r.end(), [&](const Vec3& c) { return near(c, x); });
    const auto exact = [&](std::int32_t id) { return near(r[std::size_t(id)], x); };
    hits += truth;
    disagreements += fine.any_within_one(x, exact) != truth;
    disagreements += wide.any_within_one(x, exact) != truth;
  }
  EXPECT_EQ(disagreements, 0);
  EXPECT_GT(hits, 5000);  // both answers occur often
  EXPECT_LT(hits, 15000);
}

// A dilute placement (wide cells) is a valid packing at the density asked.
TEST(RandomPlacement, NoOverlapAtPhi002) { expect_valid_packing(0.02); }

// RSA saturates near phi = 0.384; 2000 spheres at 0.39 lie far beyond the
// spread of the saturation density at that size.
TEST(RandomPlacement, BeyondSaturationIsAnInputErrorPointingToFcc) {
  try {
    initial_state(positions_only(2000, 0.39, 3));
    FAIL() << "placed 2000 spheres at phi = 0.39";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("saturat"), std::string::npos) << msg;
    EXPECT_NE(msg.find("fcc"), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
}

// The kinetic energy per particle at t = 0 is (d/2) T0 in every dimension:
// the E0 of the progress line, whose E/E0 so starts at 1 (it started at
// 0.67 for disks and 0.33 for rods when E0 was 3/2 T0 whatever d).
TEST(InitialState, TheEnergyPerParticleIsHalfTheDimensionTimesT0) {
  for (int d = 1; d <= 3; ++d) {
    const Scene s = test::in_dimension(test::elastic_scene(2000, 0.2, 3), d);
    const Particles p = initial_state(s);
    double e = 0;
    for (const Vec3& v : p.v) e += 0.5 * dot(v, v);
    EXPECT_NEAR(e / double(p.size()) / initial_energy(s), 1.0, 1e-12) << d << "D";
    EXPECT_EQ(initial_energy(s), 0.5 * d * initial_temperature(s));
  }
}

}  // namespace
}  // namespace coolgas
