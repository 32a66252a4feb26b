// The dimension of space, d = 1, 2 or 3, and everything in coolgas that
// depends on it, in one place: spheres in a periodic cube (d = 3), disks in
// a periodic square (d = 2), rods on a ring (d = 1). Every other file asks
// a Geometry instead of switching on d itself (tests/lint/dimension_switches.sh
// fails the build's tests if a switch comes back).
//
// Particles of diameter σ have mass σ^d (unit spheres, disks and rods have
// mass 1, and masses add as volumes, areas and lengths do when aggregates
// merge). phi is the fraction of the box's measure (volume, area, length)
// the particles cover: a unit sphere covers π/6 of a unit cube, a unit disk
// π/4 of a unit square, a unit rod all of a unit length. The 3D forms are the
// ones coolgas has always computed, operation for operation, so a 3D
// scene's N, L, phi and time unit stay the same to the last bit.
#pragma once
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "common/limits.h"

namespace coolgas {

class Geometry {
 public:
  // d = 1, 2 or 3; any other value is a logic error of the caller (readers
  // check a file's dimension, and the scene its key, before making one).
  constexpr explicit Geometry(int d) : d_(d) {
    if (d < 1 || d > 3) throw std::invalid_argument("the dimension of space is 1, 2 or 3, not " + std::to_string(d));
  }
  static constexpr bool valid(int d) { return d >= 1 && d <= 3; }

  constexpr int d() const { return d_; }
  // f.template operator()<d>() for a template lambda [&]<int D>() {...}: the
  // one place a run-time d picks a compile-time one (the engine's D).
  template <class F>
  decltype(auto) dispatch(F&& f) const {
    if (d_ == 1) return f.template operator()<1>();
    if (d_ == 2) return f.template operator()<2>();
    return f.template operator()<3>();
  }
  constexpr bool operator==(const Geometry&) const = default;

  // ---- Names, for messages and provenance.
  const char* particles() const { return pick("rods", "disks", "spheres"); }
  const char* box() const { return pick("ring", "square", "cube"); }
  const char* boxes() const { return pick("rings", "squares", "cubes"); }
  const char* box_adjective() const { return pick("ring", "square", "cubic"); }
  const char* space() const { return pick("line", "plane", "space"); }  // where the particles lie
  // "" in 3D, " in 2D" or " in 1D" otherwise (appended to a notice).
  std::string in_d() const { return d_ == 3 ? std::string() : " in " + std::to_string(d_) + "D"; }

  // ---- Powers: x^d and x^(1/d), exact in the forms 3D always used.
  constexpr double power(double x) const { return d_ == 3 ? x * x * x : (d_ == 2 ? x * x : x); }
  double root(double x) const { return d_ == 3 ? std::cbrt(x) : (d_ == 2 ? std::sqrt(x) : x); }
  // Cells or points along axis 0, 1, 2 of a grid of n per side: n on the
  // box's axes, 1 on those the dimension leaves at 0.
  constexpr int along(int axis, int n) const { return spans(axis) ? n : 1; }
  // Whether axis 0, 1 or 2 is one of the box's (the others stay at 0).
  constexpr bool spans(int axis) const { return axis < d_; }

  // ---- The box of side L.
  constexpr double box_measure(double L) const { return power(L); }
  // phi of N unit particles in a box of side L.
  double covered_fraction(double N, double L) const {
    if (d_ == 1) return N / L;
    return d_ == 3 ? N * M_PI / (6.0 * L * L * L) : N * M_PI / (4.0 * L * L);
  }
  // N (not rounded) at covered fraction phi in a box of side L.
  double particles_at(double phi, double L) const {
    if (d_ == 1) return phi * L;
    return d_ == 3 ? phi * 6.0 * L * L * L / M_PI : phi * 4.0 * L * L / M_PI;
  }
  // L of the box in which N unit particles cover phi.
  double box_side_for(double N, double phi) const {
    if (d_ == 1) return N / phi;
    return d_ == 3 ? std::cbrt(N * M_PI / (6.0 * phi)) : std::sqrt(N * M_PI / (4.0 * phi));
  }
  // Close packing, the densest covered fraction: rods touching round the
  // ring (1), disks in a hexagonal lattice (π/(2√3)), spheres in FCC (π/(3√2)).
  // Every start, generated or from a file, stays below it: at it nothing moves.
  double close_packing() const { return pick(1.0, M_PI / (2 * std::sqrt(3.0)), M_PI / (3 * std::sqrt(2.0))); }
  // The formula of covered_fraction, as a message shows it.
  const char* covered_fraction_formula() const { return pick("N/L", "N pi/(4 L^2)", "N pi/(6 L^3)"); }

  // The measure of a ball of radius r: a segment 2r, a disk pi r^2, a
  // sphere 4 pi r^3 / 3 (the shells of the pair distribution g(r)).
  double ball_measure(double r) const { return pick(2.0 * r, M_PI * r * r, 4.0 * M_PI * r * r * r / 3.0); }

  // ---- A particle: mass σ^d of diameter σ, and back.
  constexpr double mass_of_diameter(double sigma) const { return power(sigma); }
  double diameter_of_mass(double m) const { return root(m); }
  // The diameter of two touching particles merged, their masses adding.
  double merged_diameter(double a, double b) const {
    return d_ == 3 ? std::cbrt(a * a * a + b * b * b) : (d_ == 2 ? std::sqrt(a * a + b * b) : a + b);
  }

  // ---- Rotation (rough particles): a sphere spins about 3 axes, a disk
  // about z alone, a rod not at all (its contacts have no tangent).
  constexpr int rotational_axes() const { return pick(0, 1, 3); }
  // The moment of inertia per m a² (a the radius) of a uniform ball: 2/5 for
  // a sphere, 1/2 for a disk; and the largest any mass distribution of the
  // particle's symmetry allows, all of it on the rim: a thin shell, 2/3 (the
  // mean of x² + y² over a sphere of radius a is 2a²/3), a ring, 1.
  constexpr double uniform_inertia() const { return pick(0.0, 0.5, 0.4); }
  constexpr double largest_inertia() const { return pick(0.0, 1.0, 2.0 / 3.0); }

  // ---- Kinetic theory.
  // Kinetic energy per particle per unit temperature: E = (d/2) N T.
  constexpr double energy_per_temperature() const { return 0.5 * d_; }
  // The equilibrium pair correlation at contact g(σ) at covered fraction phi:
  // Carnahan–Starling (1 − φ/2)/(1 − φ)³ for spheres; Henderson's
  // (1 − 7φ/16)/(1 − φ)² for disks (D. Henderson, Mol. Phys. 30, 971 (1975));
  // the Tonks gas's exact 1/(1 − φ) for rods (L. Tonks, Phys. Rev. 50, 955
  // (1936): the gaps between neighbours are independent and exponential, of
  // mean (1 − φ)/n, so the density of neighbours at contact is n/(1 − φ)).
  double contact_value(double phi) const {
    if (d_ == 3) return (1.0 - 0.5 * phi) / std::pow(1.0 - phi, 3);
    if (d_ == 2) return (1.0 - 7.0 * phi / 16.0) / ((1.0 - phi) * (1.0 - phi));
    return 1.0 / (1.0 - phi);
  }
  // Whose contact value contact_value() is, for provenance and messages.
  const char* contact_value_name() const { return pick("Tonks (exact)", "Henderson", "Carnahan-Starling"); }
  // Enskog's collision frequency per particle of unit particles of mass 1 at
  // number density n, covered fraction phi and temperature T:
  // ω = (2 π^((d−1)/2) / Γ(d/2)) n g(σ) √(T/m) σ^(d−1), that is
  // 4 n g √(π T) for spheres, 2 n g √(π T) for disks, 2 n g √(T/π) for rods.
  // (The pair rate below at σ_ij = 1 and w = 2T: the same products, bit for bit.)
  double enskog_rate(double n, double phi, double T) const { return enskog_pair_rate(n, contact_value(phi), 1.0, 2.0 * T); }
  // ---- Mixtures (the scene's [[species]]).
  // The pair correlation at contact of particles of diameters a and b in a
  // mixture at covered fraction phi, xi = Σ_k phi_k / σ_k (phi_k the
  // fraction species k covers): for spheres Boublík's and Mansoori,
  // Carnahan, Starling & Leland's (J. Chem. Phys. 53, 471 (1970); 54, 1523
  // (1971)) 1/(1 − φ) + 3 ξ h/(1 − φ)² + 2 ξ² h²/(1 − φ)³, h = ab/(a + b),
  // whose equal-sphere limit (ξ = φ/σ) is Carnahan–Starling; for disks
  // Jenkins & Mancini's (J. Appl. Mech. 54, 27 (1987)) 1/(1 − φ) +
  // (9/8) ξ h/(1 − φ)², whose limit is Henderson's; for rods the Tonks
  // gas's exact 1/(1 − φ) (the gap beside a rod does not depend on the
  // species of either).
  double mixture_contact_value(double phi, double xi, double a, double b) const {
    const double h = a * b / (a + b), e = 1.0 - phi;
    if (d_ == 3) return 1.0 / e + 3.0 * xi * h / (e * e) + 2.0 * xi * xi * h * h / (e * e * e);
    if (d_ == 2) return 1.0 / e + 9.0 / 8.0 * xi * h / (e * e);
    return 1.0 / e;
  }
  // Whose mixture contact value it is, for messages.
  const char* mixture_contact_value_name() const { return pick("Tonks (exact)", "Jenkins-Mancini", "BMCSL"); }
  // Enskog's rate of collisions of one particle of species i with those of
  // species j (number density n_j, contact value g_ij, contact distance
  // σ_ij) whose Maxwellians are at temperatures T_i, T_j, given
  // w = T_i/m_i + T_j/m_j, the variance of their relative velocity per
  // component: the equal-particle formula of enskog_rate with
  // σ^(d−1) → σ_ij^(d−1) and T/m → w/2, that is 4 n g σ² √(π w/2) for
  // spheres, 2 n g σ √(π w/2) for disks, 2 n g √(w/(2π)) for rods (at
  // equal temperatures w/2 = T/(2 μ_ij), μ_ij the reduced mass).
  double enskog_pair_rate(double n_j, double g_ij, double sigma_ij, double w) const {
    const double t = 0.5 * w;
    if (d_ == 1) return 2.0 * n_j * g_ij * std::sqrt(t / M_PI);
    return (d_ == 3 ? 4.0 * sigma_ij * sigma_ij : 2.0 * sigma_ij) * n_j * g_ij * std::sqrt(M_PI * t);
  }
  // The temperature at which ω = 1, i.e. the mean collision time is the
  // time unit: 1/(π (4 n g)²) in 3D, 1/(π (2 n g)²) in 2D, π/(2 n g)² in 1D.
  double unit_time_temperature(double n, double phi) const {
    if (d_ == 1) {
      const double a = 2.0 * n * contact_value(phi);
      return M_PI / (a * a);
    }
    const double a = (d_ == 3 ? 4.0 : 2.0) * n * contact_value(phi);
    return 1.0 / (M_PI * a * a);
  }

  // ---- Grids of unit cells: floor(L)^d of them, 32-bit indices.
  // The largest side s with s^d <= 2^31 − 1: 1290, 46340, 2^31 − 1.
  std::int64_t max_grid_side() const {
    auto s = std::int64_t(std::floor(root(double(kMaxIndex32))));
    while (grid_cells(s + 1) <= double(kMaxIndex32)) ++s;
    while (grid_cells(s) > double(kMaxIndex32)) --s;
    return s;
  }
  // floor(L)^d, the unit cells of a box of side L (as a double: it may be huge).
  double grid_cells(double L) const { return power(std::floor(L)); }
  // The grid limit as a message states it: "L < 1291" in 3D.
  std::string grid_limit() const { return "L < " + std::to_string(max_grid_side() + 1); }

 private:
  template <class T>
  constexpr T pick(T one, T two, T three) const { return d_ == 1 ? one : (d_ == 2 ? two : three); }
  int d_;
};

}  // namespace coolgas
