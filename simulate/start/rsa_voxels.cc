#include "simulate/start/rsa_voxels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/error.h"
#include "simulate/engine/cell_grid.h"
#include "simulate/start/rsa_centre_grid.h"
#include "simulate/start/rsa_free_voxels.h"

namespace coolgas {

namespace {

// Plain trials are judged in windows of this many; when fewer than
// kSwitchAcceptance of a window succeed (the success rate of a plain trial is
// the free volume fraction), the voxel phase takes over.
constexpr std::int64_t kWindow = 4096;
constexpr double kSwitchAcceptance = 0.02;
// Total trials per sphere before giving up (only reachable if a finest voxel
// keeps a free set of measure zero, which needs a degenerate arrangement).
constexpr double kMaxTrialsPerSphere = 2000;
// The trial test of the voxel phase works on centres whose offsets are
// rounded to single precision (~1e-7): squared distances this close to 1 are
// settled on the exact positions.
constexpr double kUnsure = 1e-5;
// How many plain trials ahead the cells to search are fetched.
constexpr int kLookahead = 16;
// Below this target density the plain trials place every sphere (their
// success rate, the free volume fraction, stays far above the switch's 2 %),
// so the centres' grid needs no cells one diameter wide: cells of the mean
// spacing hold about one centre each. At phi = 0.005 and N = 8e6 (L = 943)
// one-diameter cells would be 8.4e8, 17 GB.
constexpr double kWideCellsBelowPhi = 0.1;

double centre_cell_width(double L, std::int64_t N) {
  const double volume = L * L * L;
  const bool dilute = N > 0 && double(N) * M_PI / (6.0 * volume) < kWideCellsBelowPhi;
  return dilute ? std::cbrt(volume / double(N)) : 1.0;
}

// The grid needs three cells of one diameter along each side of the box.
double checked_side(double L) {
  const std::string err = check_box_fits_grid(L, 1.0);
  if (!err.empty()) throw std::invalid_argument(err);
  return L;
}

class Placer {
 public:
  // N: the spheres to be placed (it sets the grid's cell width).
  Placer(Particles& p, std::int64_t N, InterruptFlag interrupt, PlacementReport report = {})
      : p_(p),
        grid_(checked_side(p.L), centre_cell_width(p.L, N)),
        L_(p.L),
        half_(p.L / 2),
        top_(std::nextafter(p.L, 0.0)),
        interrupt_(interrupt),
        report_(std::move(report)) {}

  // Places spheres 0, 1, ... up to N; returns how many fit (N unless no room
  // is left before, or the trial budget runs out).
  std::int64_t fill(std::int64_t N, Random& rng);

 private:
  // Minimum image of a coordinate difference (|d| < L; L >= 3 > 2 diameters).
  double image(double d) const { return d > half_ ? d - L_ : (d < -half_ ? d + L_ : d); }
  bool overlap(const Vec3& r, const Vec3& x) const {
    const double dx = image(r.x - x.x), dy = image(r.y - x.y), dz = image(r.z - x.z);
    return dx * dx + dy * dy + dz * dz < 1.0;
  }
  bool overlaps(const Vec3& x) const {
    return grid_.any_within_one(x, [&](std::int32_t id) { return overlap(p_.r[std::size_t(id)], x); });
  }
  Vec3 uniform_in(const Vec3& lo, double side, Random& rng) const {
    Vec3 x;
    for (int d = 0; d < 3; ++d) x[d] = std::min(lo[d] + side * rng.uniform(), top_);
    return x;
  }
  Vec3 relative(const Vec3& r, const Vec3& corner) const {
    return {image(r.x - corner.x), image(r.y - corner.y), image(r.z - corner.z)};
  }
  // Every kWindow trials: stop if asked to, and say how far the placement is.
  void check_in(std::int64_t placed) const {
    throw_if_interrupted(interrupt_);
    if (report_) report_(placed);
  }
  void place(std::int64_t i, const Vec3& x) {
    p_.r[std::size_t(i)] = x;
    grid_.insert(x, std::int32_t(i));
  }

  std::int64_t plain_phase(std::int64_t N, Random& rng);
  std::int64_t voxel_phase(std::int64_t i, std::int64_t N, Random& rng);
  void gather_near(std::size_t cell);
  bool near_overlaps(const Vec3& x, const Vec3& corner) const;
  const std::vector<Vec3>& exact_near(const Vec3& corner);
  void cover_around(FreeVoxels& voxels, const Vec3& x) const;

  Particles& p_;
  CentreGrid grid_;
  double L_, half_, top_;
  InterruptFlag interrupt_;
  PlacementReport report_;  // may be empty
  std::int64_t since_check_ = 0;  // voxel trials since the interrupt flag was last looked at
  double trials_ = 0;
  std::vector<Vec3> near_;  // scratch: the centres around one cell, relative to its corner,
  std::vector<std::int32_t> near_ids_;  // and their ids
  std::vector<Vec3> exact_;  // scratch: their exact positions relative to the corner
};

std::int64_t Placer::fill(std::int64_t N, Random& rng) {
  const std::int64_t i = plain_phase(N, rng);
  if (i == N) return N;
  // The voxels are cut from one-diameter cells; a grid of wider cells (not
  // expected to get here) is filed again. One-diameter cells are at most 4/3
  // wide (L >= 3), the dilute ones at least (pi / (6 * 0.1))^(1/3) = 1.74.
  if (grid_.width() > 1.5) {
    grid_ = CentreGrid(L_);
    for (std::int64_t k = 0; k < i; ++k) grid_.insert(p_.r[std::size_t(k)], std::int32_t(k));
  }
  return voxel_phase(i, N, rng);
}

// Uniform trials over the box, rejected if overlapping, while they mostly
// succeed. Returns the number placed.
std::int64_t Placer::plain_phase(std::int64_t N, Random& rng) {
  // The trial points do not depend on the outcomes: a copy of the generator
  // runs kLookahead trials ahead and asks the memory for the cell each will
  // search first.
  Random ahead = rng;
  for (int k = 0; k < kLookahead; ++k) grid_.prefetch(uniform_in({0, 0, 0}, L_, ahead));
  std::int64_t i = 0;
  for (std::int64_t window_hits = 0, window = 0; i < N;) {
    const Vec3 x = uniform_in({0, 0, 0}, L_, rng);
    grid_.prefetch(uniform_in({0, 0, 0}, L_, ahead));
    ++trials_;
    if (!overlaps(x)) {
      place(i++, x);
      ++window_hits;
    }
    if (++window == kWindow) {
      check_in(i);
      if (double(window_hits) < kSwitchAcceptance * double(kWindow)) break;
      window = window_hits = 0;
    }
  }
  return i;
}

// Zhang & Torquato's voxel method: a voxel drawn by volume, a uniform point
// in it, rejected if overlapping. Every point of the union of the voxels is
// equally likely and the union holds all the free space, so an accepted
// point is uniform over the free space: the process is still exact RSA.
std::int64_t Placer::voxel_phase(std::int64_t i, std::int64_t N, Random& rng) {
  const double budget = kMaxTrialsPerSphere * double(N);
  FreeVoxels voxels(grid_.cells_per_side(), grid_.width());
  voxels.build([&](auto&& f) { grid_.for_each_centre(f); });
  while (i < N) {
    if (trials_ > budget || voxels.empty()) break;
    if (++since_check_ == kWindow) {
      since_check_ = 0;
      check_in(i);
    }
    const FreeVoxels::Voxel v = voxels.draw(rng);
    const Vec3 corner = grid_.corner(v.cell);
    const Vec3 x = uniform_in({corner.x + v.lo.x, corner.y + v.lo.y, corner.z + v.lo.z}, v.side, rng);
    ++trials_;
    FreeVoxels::Guess next = voxels.guess(rng);
    // One pass over the 27 cells serves the trial test and, if it fails, the refinement.
    gather_near(v.cell);
    voxels.narrow(next);
    if (near_overlaps(x, corner)) {
      if (!voxels.refine(v, near_)) voxels.settle(v, exact_near(corner));
    } else {
      place(i++, x);
      cover_around(voxels, x);
    }
    const std::int64_t guessed = voxels.land(next);
    if (guessed >= 0) grid_.prefetch_near(std::size_t(guessed));
  }
  return i;
}

void Placer::gather_near(std::size_t cell) {
  near_.clear();
  near_ids_.clear();
  grid_.for_each_near(cell, [&](const Vec3& r, std::int32_t id) {
    near_.push_back(r);
    near_ids_.push_back(id);
  });
}

// Whether x (in the cell with the given corner) overlaps a gathered centre.
bool Placer::near_overlaps(const Vec3& x, const Vec3& corner) const {
  const Vec3 u{x.x - corner.x, x.y - corner.y, x.z - corner.z};
  for (std::size_t j = 0; j < near_.size(); ++j) {
    const double dx = near_[j].x - u.x, dy = near_[j].y - u.y, dz = near_[j].z - u.z;
    const double d2 = dx * dx + dy * dy + dz * dz;
    if (d2 < 1.0 - kUnsure) return true;
    if (d2 <= 1.0 + kUnsure && overlap(p_.r[std::size_t(near_ids_[j])], x)) return true;
  }
  return false;
}

// The gathered centres' exact positions, relative to the corner of their cell.
const std::vector<Vec3>& Placer::exact_near(const Vec3& corner) {
  exact_.clear();
  for (const std::int32_t id : near_ids_) exact_.push_back(relative(p_.r[std::size_t(id)], corner));
  return exact_;
}

// Removes the voxels that the exclusion sphere of a new centre at x covers.
void Placer::cover_around(FreeVoxels& voxels, const Vec3& x) const {
  int cell[3];
  Vec3 offset;
  grid_.locate(x, cell, offset);
  voxels.cover(cell[0], cell[1], cell[2], offset);
}

[[noreturn]] void saturated(double L, std::int64_t placed, std::int64_t N) {
  char reached[32];
  std::snprintf(reached, sizeof reached, "%.4f", double(placed) * M_PI / (6.0 * L * L * L));
  throw InputError(std::string("random sequential addition saturated at phi = ") + reached + " (placed " +
                   std::to_string(placed) + " of " + std::to_string(N) +
                   " spheres: no room is left for another); use system.init = \"fcc\" or a lower phi");
}

}  // namespace

void place_random_sequential(Particles& p, std::int64_t N, Random& rng, InterruptFlag interrupt,
                             const PlacementReport& report) {
  Placer placer(p, N, interrupt, report);
  const std::int64_t placed = placer.fill(N, rng);
  if (placed < N) saturated(p.L, placed, N);
}

std::int64_t saturate_random_sequential(double L, Random& rng) {
  Particles p;
  p.L = L;
  // More than fit: unit spheres pack at most sqrt(2) per unit volume.
  p.r.resize(std::size_t(std::sqrt(2.0) * L * L * L) + 1);
  Placer placer(p, 0, nullptr);
  return placer.fill(std::int64_t(p.r.size()), rng);
}

}  // namespace coolgas
