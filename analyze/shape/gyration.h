// The shape of a set of unit-mass points: its gyration tensor
//   G_ab = (1/M) sum_j (r_ja - rbar_a)(r_jb - rbar_b),
// eigenvalues l1 <= l2 <= l3 (Eigen's SelfAdjointEigenSolver), and the
// invariants built from them:
//   radius of gyration  R_g^2 = l1 + l2 + l3;
//   asphericity         A = (3/2) sum_i (l_i - lbar)^2 / (sum_i l_i)^2, 0 (sphere) .. 1 (rod)
//                       (Rudnick & Gaspari, J. Phys. A 19, L191 (1986));
//   prolateness         P = 27 prod_i (l_i - lbar) / (sum_i l_i)^3, -1/4 (disc) .. 2 (rod)
//                       (Dima & Thirumalai, J. Phys. Chem. B 108, 6564 (2004)),
// with lbar = (l1 + l2 + l3)/3. A set of one point has R_g = A = P = 0.
// In 2D (points in the plane z = 0) the tensor is 2 x 2, eigenvalues
// l1 <= l2, R_g^2 = l1 + l2, and the asphericity is normalised the same way
// for d dimensions, A = (d/(d-1)) sum_i (l_i - lbar)^2 / (sum_i l_i)^2
// = ((l2 - l1)/(l1 + l2))^2: 0 for a disc or square, 1 for a rod; the
// prolateness is a 3D invariant (0 in 2D, and no column of the 2D tables).
// In 1D (points on the x axis) the "tensor" is the one number l1 = <x^2> -
// <x>^2 = R_g^2; no shape invariant is left (asphericity and prolateness 0,
// and no columns of the 1D tables).
#pragma once
#include <array>
#include <cstdint>

#include "common/geometry.h"

namespace coolgas {

// Accumulates points relative to a reference point near them (so that the
// sums of squares do not cancel in round-off).
struct GyrationSums {
  std::int64_t mass = 0;
  double s[3] = {0, 0, 0};
  double ss[6] = {0, 0, 0, 0, 0, 0};  // xx yy zz xy xz yz
  void add(double x, double y, double z) {
    ++mass;
    s[0] += x, s[1] += y, s[2] += z;
    ss[0] += x * x, ss[1] += y * y, ss[2] += z * z, ss[3] += x * y, ss[4] += x * z, ss[5] += y * z;
  }
};

struct Shape {
  std::int64_t mass = 0;
  std::array<double, 3> lambda{};  // ascending; in 2D the first two (the third 0), in 1D the first
  double Rg = 0, asphericity = 0, prolateness = 0;
};

// The shape of the points of a space of dimension d = geometry.d(): in 2D every z = 0, in 1D every y and z = 0.
Shape shape_of(const GyrationSums& g, Geometry geometry);

}  // namespace coolgas
